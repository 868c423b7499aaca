// The 3D view: every vehicle at the simulator's truth and, ghosted, at the estimate, their trails,
// the reference, the uploaded trajectory, the thrust vector and the disturbance force. World z is
// up (docs/architecture.md §3); quaternions arrive w, x, y, z and three.js takes x, y, z, w.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const ARM = 0.125;          // [m] config/quad255.yaml vehicle.arm_length, X layout
const ROTOR_RADIUS = 0.064; // [m] a 5-inch propeller
const TRAIL_POINTS = 3000;
const GRAVITY = 9.81;       // [m/s^2] the thrust arrow: hover thrust draws two arm lengths
const COLORS = [0xf07010, 0x10a0f0, 0x30c050, 0xc040c0];
const RENDER_PERIOD_MS = 1000 / 30 - 2;  // a 60 Hz display's every other frame

function vehicleModel(color, opacity) {
  const group = new THREE.Group();
  const material = (c) => new THREE.MeshStandardMaterial({ color: c, transparent: opacity < 1, opacity });
  for (const yaw of [Math.PI / 4, -Math.PI / 4]) {
    const arm = new THREE.Mesh(new THREE.BoxGeometry(2 * ARM, 0.012, 0.008), material(0x333338));
    arm.rotation.z = yaw;
    group.add(arm);
  }
  group.add(new THREE.Mesh(new THREE.BoxGeometry(0.06, 0.05, 0.03), material(color)));
  const s = Math.SQRT1_2 * ARM;
  for (const [x, y] of [[s, -s], [-s, s], [s, s], [-s, -s]]) {  // FR, BL, FL, BR
    const rotor = new THREE.Mesh(new THREE.CylinderGeometry(ROTOR_RADIUS, ROTOR_RADIUS, 0.004, 24),
      material(x > 0 ? color : 0x555560));
    rotor.rotation.x = Math.PI / 2;  // the cylinder's axis (y) along body z
    rotor.position.set(x, y, 0.012);
    group.add(rotor);
  }
  if (opacity >= 1) group.add(new THREE.AxesHelper(0.15));
  return group;
}

function line(color, capacity) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(3 * capacity), 3));
  geometry.setDrawRange(0, 0);
  const object = new THREE.Line(geometry, new THREE.LineBasicMaterial({ color }));
  object.frustumCulled = false;
  return { object, capacity, count: 0 };
}

function setLine(l, points) {
  const a = l.object.geometry.attributes.position;
  l.count = Math.min(points.length, l.capacity);
  for (let i = 0; i < l.count; i++) a.setXYZ(i, points[i][0], points[i][1], points[i][2]);
  a.needsUpdate = true;
  l.object.geometry.setDrawRange(0, l.count);
}

// A trail keeps a point once it is 1 cm from the last; the oldest go past its capacity.
function extendTrail(l, p) {
  const a = l.object.geometry.attributes.position;
  if (l.count > 0) {
    const i = l.count - 1;
    if (Math.hypot(a.getX(i) - p[0], a.getY(i) - p[1], a.getZ(i) - p[2]) < 0.01) return;
  }
  if (l.count === l.capacity) {
    a.array.copyWithin(0, 3);
    l.count -= 1;
  }
  a.setXYZ(l.count, p[0], p[1], p[2]);
  l.count += 1;
  a.needsUpdate = true;
  l.object.geometry.setDrawRange(0, l.count);
}

const setQuaternion = (object, q) => object.quaternion.set(q[1], q[2], q[3], q[0]);

class VehicleView {
  constructor(scene, index) {
    const color = COLORS[index % COLORS.length];
    this.body = vehicleModel(color, 1);
    this.ghost = vehicleModel(0x4080ff, 0.3);
    this.thrust = new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(), 0.1, 0xffcc00, 0.03, 0.02);
    this.body.add(this.thrust);
    this.force = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), new THREE.Vector3(), 0.1, 0xc020c0, 0.05, 0.03);
    this.force.visible = false;
    this.truthTrail = line(color, TRAIL_POINTS);
    this.estimateTrail = line(0x4080ff, TRAIL_POINTS);
    this.path = line(0x999999, 20000);
    this.reference = new THREE.Mesh(new THREE.SphereGeometry(0.02, 16, 8), new THREE.MeshBasicMaterial({ color: 0x20c050 }));
    this.body.visible = this.ghost.visible = this.reference.visible = false;
    for (const o of [this.body, this.ghost, this.force, this.truthTrail.object, this.estimateTrail.object,
      this.path.object, this.reference]) scene.add(o);
    this.truthUtime = null;
    this.estimateUtime = null;
    this.forceDrawn = 0;  // truth messages drawn with a disturbance force
  }

  onTruth(m) {
    this.body.position.set(m.position[0], m.position[1], m.position[2]);
    setQuaternion(this.body, m.orientation);
    this.body.visible = true;
    this.truthUtime = m.utime;
    extendTrail(this.truthTrail, m.position);
    const f = m.external_force.map((v) => v ?? 0);
    const norm = Math.hypot(f[0], f[1], f[2]);
    this.force.visible = norm > 1e-6;
    if (this.force.visible) {  // 1 N drawn 0.5 m long
      this.forceDrawn += 1;
      this.force.position.copy(this.body.position);
      this.force.setDirection(new THREE.Vector3(f[0] / norm, f[1] / norm, f[2] / norm));
      this.force.setLength(0.5 * norm, 0.05, 0.03);
    }
  }

  onEstimate(m) {
    this.ghost.position.set(m.position[0], m.position[1], m.position[2]);
    setQuaternion(this.ghost, m.orientation);
    this.ghost.visible = true;
    this.estimateUtime = m.utime;
    extendTrail(this.estimateTrail, m.position);
  }

  onReference(m) {
    this.reference.position.set(m.x[0], m.x[1], m.x[2]);
    this.reference.visible = true;
  }

  onTrajectory(m) { setLine(this.path, m.x.map((x) => [x[0], x[1], x[2]])); }

  onRateCommand(m) {  // collective thrust along body z: hover thrust draws 2 arm lengths
    this.thrust.setLength(Math.max(1e-3, 2 * ARM * Math.max(0, m.thrust ?? 0) / GRAVITY), 0.03, 0.02);
  }

  clearTrails() {
    for (const t of [this.truthTrail, this.estimateTrail]) {
      t.count = 0;
      t.object.geometry.setDrawRange(0, 0);
    }
  }

  // What is drawn, as the test reads it: the pose of the three.js objects themselves.
  state() {
    const pose = (o, utime) => (utime === null ? null : {
      utime, position: o.position.toArray(), quaternion: [o.quaternion.w, o.quaternion.x, o.quaternion.y, o.quaternion.z],
    });
    return {
      truth: pose(this.body, this.truthUtime), estimate: pose(this.ghost, this.estimateUtime),
      truthTrailPoints: this.truthTrail.count, estimateTrailPoints: this.estimateTrail.count,
      pathPoints: this.path.count, reference: this.reference.visible ? this.reference.position.toArray() : null,
      forceShown: this.force.visible, forceDrawn: this.forceDrawn,
    };
  }
}

export class SceneView {
  constructor(canvas) {
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0xf4f5f7);
    this.camera = new THREE.PerspectiveCamera(50, 1, 0.01, 200);
    this.camera.up.set(0, 0, 1);
    this.camera.position.set(-0.9, -1.3, 1.6);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.target.set(0, 0, 0.9);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x888899, 2.0));
    const sun = new THREE.DirectionalLight(0xffffff, 1.5);
    sun.position.set(2, -3, 5);
    this.scene.add(sun);
    const grid = new THREE.GridHelper(10, 20, 0x999999, 0xcccccc);
    grid.rotation.x = Math.PI / 2;  // into the x-y plane: the ground, z up
    this.scene.add(grid);
    this.scene.add(new THREE.AxesHelper(0.5));
    this.vehicles = new Map();
    this.dirty = true;
    this.renders = 0;
    this.followed = null;
    this.controls.addEventListener('change', () => { this.dirty = true; });
    new ResizeObserver(() => this.resize()).observe(canvas);
    this.resize();
    // At most 30 renders a second, and only when something moved: without a GPU (SwiftShader,
    // headless) a render is CPU time taken from the machine that flies.
    let last = 0;
    const loop = (now) => {
      if (this.dirty && now - last >= RENDER_PERIOD_MS) {
        last = now;
        this.render();
      }
      requestAnimationFrame(loop);
    };
    requestAnimationFrame(loop);
  }

  vehicle(name) {
    if (!this.vehicles.has(name)) this.vehicles.set(name, new VehicleView(this.scene, this.vehicles.size));
    this.dirty = true;
    return this.vehicles.get(name);
  }

  follow(name) { this.followed = name; }

  resize() {
    const c = this.renderer.domElement;
    this.renderer.setSize(c.clientWidth, c.clientHeight, false);
    this.camera.aspect = c.clientWidth / Math.max(1, c.clientHeight);
    this.camera.updateProjectionMatrix();
    this.dirty = true;
  }

  render() {
    const v = this.vehicles.get(this.followed);
    if (v && v.body.visible) {  // keep the followed vehicle in view, the camera's offset unchanged
      const shift = v.body.position.clone().sub(this.controls.target);
      this.controls.target.add(shift);
      this.camera.position.add(shift);
    }
    this.controls.update();
    this.renderer.render(this.scene, this.camera);
    this.renders += 1;
    this.dirty = false;
  }

  state() {
    const vehicles = {};
    for (const [name, v] of this.vehicles) vehicles[name] = v.state();
    return { vehicles, renders: this.renders, webgl2: this.renderer.capabilities.isWebGL2 };
  }
}
