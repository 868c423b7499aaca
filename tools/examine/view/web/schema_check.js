// What the page reads of each message type, checked against the JSON Schema the server advertises
// (generated from lcmtypes/*.lcm) before a channel is drawn, and against every message it
// receives: a renamed or reshaped field shows as a schema error on the page and in its state,
// never as a vehicle drawn from the wrong numbers.

const vec = (n) => ({ array: n, of: 'number' });

// type name -> field -> 'integer' | 'number' | 'string' | {array: n, of: ...}
export const EXPECTED = {
  sim_truth_t: { utime: 'integer', position: vec(3), orientation: vec(4), external_force: vec(3) },
  state_estimate_t: { utime: 'integer', position: vec(3), orientation: vec(4), body_rate: vec(3) },
  reference_t: { utime: 'integer', x: vec(10) },
  trajectory_t: { utime: 'integer', num_samples: 'integer', x: { array: 'num_samples', of: vec(10) } },
  rate_cmd_t: { utime: 'integer', body_rate: vec(3), thrust: 'number', thrust_demand: 'number' },
  gains_t: { utime: 'integer', solve_us: 'number' },
  heartbeat_t: {
    utime: 'integer', process: 'string', state: 'integer', cpu_percent: 'number', deadline_misses: 'integer',
    dropped: 'integer', rejected: 'integer', errors: 'integer', last_error: 'string',
  },
};

const typeOfSchema = (s) => (Array.isArray(s.type) ? s.type : [s.type]);

function schemaMatches(expected, schema, path, errors) {
  if (!schema) return errors.push(`${path}: missing`);
  if (typeof expected === 'string') {
    const types = typeOfSchema(schema);
    const ok = expected === 'number' ? types.includes('number') : types.includes(expected);
    if (!ok) errors.push(`${path}: expected ${expected}, schema says ${JSON.stringify(schema.type)}`);
    return;
  }
  if (!typeOfSchema(schema).includes('array')) return errors.push(`${path}: expected an array`);
  if (typeof expected.array === 'number' && !(schema.minItems === expected.array && schema.maxItems === expected.array)) {
    errors.push(`${path}: expected ${expected.array} elements, schema says ${schema.minItems}..${schema.maxItems}`);
  }
  schemaMatches(expected.of, schema.items, `${path}[]`, errors);
}

// The errors of an advertised channel's schema for what the page reads ([] when it fits).
export function checkSchema(typeName, schemaText) {
  const expected = EXPECTED[typeName];
  if (!expected) return [];
  let schema;
  try {
    schema = JSON.parse(schemaText);
  } catch (e) {
    return [`${typeName}: schema is not JSON`];
  }
  const errors = [];
  for (const [field, want] of Object.entries(expected)) {
    schemaMatches(want, schema.properties && schema.properties[field], `${typeName}.${field}`, errors);
  }
  return errors;
}

function valueMatches(expected, value, message) {
  if (expected === 'integer') return Number.isInteger(value);
  if (expected === 'number') return value === null || typeof value === 'number';
  if (expected === 'string') return typeof value === 'string';
  const n = typeof expected.array === 'number' ? expected.array : message[expected.array];
  return Array.isArray(value) && value.length === n && value.every((v) => valueMatches(expected.of, v, message));
}

// The first field of a received message that does not have the shape the page reads, or null.
export function checkMessage(typeName, message) {
  const expected = EXPECTED[typeName];
  if (!expected) return null;
  for (const [field, want] of Object.entries(expected)) {
    if (!valueMatches(want, message[field], message)) return `${typeName}.${field}`;
  }
  return null;
}
