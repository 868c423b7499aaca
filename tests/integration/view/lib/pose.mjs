// Drawn poses (the page's scene state) against the log's rows of the same utime.

// The angle between two unit quaternions (w, x, y, z), q and -q being the same attitude.
export function angleDeg(a, b) {
  const dot = Math.abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]);
  return (2 * Math.acos(Math.min(1, dot)) * 180) / Math.PI;
}

// states: page states; key: 'truth' or 'estimate'; csv: that vehicle's SIM_TRUTH or STATE_EST.
// {matched, maxDistance [m], maxAngle [deg], span [m]: the largest extent of the matched poses}
export function poseErrors(states, csv, vehicle, key) {
  const utime = csv.column('utime');
  const byUtime = new Map(csv.rows.map((r) => [r[utime], r]));
  let matched = 0, maxDistance = 0, maxAngle = 0;
  const positions = [];
  for (const state of states) {
    const drawn = state.vehicles[vehicle]?.[key];
    const row = drawn && byUtime.get(String(drawn.utime));
    if (!row) continue;
    matched += 1;
    const p = [0, 1, 2].map((i) => Number(row[csv.column(`position[${i}]`)]));
    const q = [0, 1, 2, 3].map((i) => Number(row[csv.column(`orientation[${i}]`)]));
    maxDistance = Math.max(maxDistance, Math.hypot(...p.map((v, i) => v - drawn.position[i])));
    maxAngle = Math.max(maxAngle, angleDeg(q, drawn.quaternion));
    positions.push(p);
  }
  const extent = (i) => Math.max(...positions.map((p) => p[i])) - Math.min(...positions.map((p) => p[i]));
  return { matched, maxDistance, maxAngle, span: positions.length ? Math.max(extent(0), extent(1), extent(2)) : 0 };
}

export const describe = (e) => `largest error ${(100 * e.maxDistance).toFixed(4)} cm, ${e.maxAngle.toFixed(4)} deg`;
