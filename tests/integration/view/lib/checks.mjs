// Named checks: each prints PASS or FAIL with its name and what it measured; fail() sets the exit
// code. A negative asserts that a check fails, and for the reason named.
export class Checks {
  constructor(prefix) { this.prefix = prefix; this.failed = []; this.results = new Map(); }

  check(name, ok, detail) {
    this.results.set(name, { ok, detail });
    console.log(`${ok ? 'PASS' : 'FAIL'} ${this.prefix}.${name}: ${detail}`);
    if (!ok) this.failed.push(name);
    return ok;
  }

  report(text) { console.log(`     ${this.prefix}: ${text}`); }

  exitCode() {
    if (this.results.size === 0) { console.log(`FAIL ${this.prefix}: no check ran`); return 1; }
    console.log(`${this.prefix}: ${this.results.size - this.failed.length} of ${this.results.size} checks pass` +
      (this.failed.length ? `; FAILED: ${this.failed.join(', ')}` : ''));
    return this.failed.length ? 1 : 0;
  }
}

// Runs `judge(checks)` on input meant to fail and asserts it fails check `name` with `reason` in its detail.
export function expectFailure(outer, label, name, reason, judge) {
  const inner = new Checks(`${outer.prefix}.negative.${label}`);
  const log = console.log;
  console.log = () => {};
  try { judge(inner); } finally { console.log = log; }
  const r = inner.results.get(name);
  outer.check(`negative_${label}`, r !== undefined && !r.ok && String(r.detail).includes(reason),
    r ? `${name} ${r.ok ? 'PASSED (should fail)' : 'failed'}: ${r.detail}` : `${name} never ran`);
}
