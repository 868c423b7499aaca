// Strip charts on a 2D canvas: the last WINDOW_S seconds of simulation time of a few series each.
// Points arrive at the pace of the stream (at most 60 a second per channel); a chart redraws at
// most 10 times a second.

const WINDOW_S = 10;
const MAX_POINTS = 1200;  // per series: 60 a second for 20 s
const REDRAW_MS = 99;

export class StripChart {
  // series: [{name, color, dash}]
  constructor(canvas, title, unit, series) {
    this.canvas = canvas;
    this.title = title;
    this.unit = unit;
    this.series = series.map((s) => ({ ...s, t: [], v: [] }));
    this.points = 0;  // received, in all
    this.lastT = null;
    this.lastDraw = 0;
    this.draws = 0;
  }

  add(index, t, value) {
    if (value === null || !Number.isFinite(value)) return;
    const s = this.series[index];
    if (s.t.length && t < s.t[s.t.length - 1]) {  // time went back: a new flight or a seek
      s.t.length = 0;
      s.v.length = 0;
    }
    s.t.push(t);
    s.v.push(value);
    if (s.t.length > MAX_POINTS) {
      s.t.splice(0, s.t.length - MAX_POINTS);
      s.v.splice(0, s.v.length - MAX_POINTS);
    }
    this.points += 1;
    this.lastT = t;
  }

  clear() {
    for (const s of this.series) { s.t.length = 0; s.v.length = 0; }
  }

  draw(now) {
    if (now - this.lastDraw < REDRAW_MS) return;
    this.lastDraw = now;
    const c = this.canvas;
    const w = (c.width = c.clientWidth * devicePixelRatio);
    const h = (c.height = c.clientHeight * devicePixelRatio);
    const g = c.getContext('2d');
    g.scale(devicePixelRatio, devicePixelRatio);
    const W = c.clientWidth, H = c.clientHeight, left = 46, top = 16, bottom = 16;
    g.clearRect(0, 0, w, h);
    g.font = '11px sans-serif';
    g.fillStyle = '#222';
    g.fillText(`${this.title} [${this.unit}]`, left, 11);
    const t1 = this.lastT ?? WINDOW_S, t0 = t1 - WINDOW_S;
    let lo = Infinity, hi = -Infinity;
    for (const s of this.series) {
      for (let i = 0; i < s.t.length; i++) if (s.t[i] >= t0) { lo = Math.min(lo, s.v[i]); hi = Math.max(hi, s.v[i]); }
    }
    if (!Number.isFinite(lo)) { lo = -1; hi = 1; }
    if (hi - lo < 1e-9) { lo -= 0.5; hi += 0.5; }
    const x = (t) => left + ((t - t0) / WINDOW_S) * (W - left - 6);
    const y = (v) => top + (1 - (v - lo) / (hi - lo)) * (H - top - bottom);
    g.strokeStyle = '#ddd';
    g.strokeRect(left, top, W - left - 6, H - top - bottom);
    g.fillStyle = '#555';
    g.fillText(hi.toPrecision(3), 2, top + 8);
    g.fillText(lo.toPrecision(3), 2, H - bottom);
    g.fillText(`t = ${t1.toFixed(1)} s`, W - 70, H - 3);
    let legend = left + g.measureText(`${this.title} [${this.unit}]`).width + 12;
    for (const s of this.series) {
      g.strokeStyle = s.color;
      g.setLineDash(s.dash ? [4, 3] : []);
      g.beginPath();
      let first = true;
      for (let i = 0; i < s.t.length; i++) {
        if (s.t[i] < t0) continue;
        if (first) g.moveTo(x(s.t[i]), y(s.v[i])); else g.lineTo(x(s.t[i]), y(s.v[i]));
        first = false;
      }
      g.stroke();
      if (!s.name) continue;  // a series that shares its colour's legend entry
      g.fillStyle = s.color;
      g.fillText(s.name, legend, 11);
      legend += g.measureText(s.name).width + 10;
    }
    g.setLineDash([]);
    this.draws += 1;
  }

  state() { return { points: this.points, lastT: this.lastT, draws: this.draws }; }
}
