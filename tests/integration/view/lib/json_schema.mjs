// Checks a value against the JSON Schema subset sdlqr's generated schemas and Foxglove's own use:
// type (one or a list), properties, required, additionalProperties false, items, minItems,
// maxItems, minimum, maximum, oneOf of const. Returns the first violation's path, or null.
const isType = (v, t) => ({
  object: v !== null && typeof v === 'object' && !Array.isArray(v), array: Array.isArray(v), string: typeof v === 'string',
  boolean: typeof v === 'boolean', null: v === null, integer: Number.isInteger(v), number: typeof v === 'number',
})[t];

export function violation(value, schema, path = '$') {
  if (schema.type !== undefined && !(Array.isArray(schema.type) ? schema.type : [schema.type]).some((t) => isType(value, t))) {
    return `${path}: not ${JSON.stringify(schema.type)}`;
  }
  if (schema.oneOf && !schema.oneOf.some((s) => s.const === value)) return `${path}: not one of the constants`;
  if (typeof value === 'number') {
    if (schema.minimum !== undefined && value < schema.minimum) return `${path}: below minimum`;
    if (schema.maximum !== undefined && value > schema.maximum) return `${path}: above maximum`;
  }
  if (Array.isArray(value)) {
    if (schema.minItems !== undefined && value.length < schema.minItems) return `${path}: too few items`;
    if (schema.maxItems !== undefined && value.length > schema.maxItems) return `${path}: too many items`;
    for (let i = 0; i < value.length && schema.items; i++) {
      const v = violation(value[i], schema.items, `${path}[${i}]`);
      if (v) return v;
    }
  } else if (isType(value, 'object')) {
    for (const key of schema.required ?? []) if (!(key in value)) return `${path}.${key}: missing`;
    for (const [key, member] of Object.entries(value)) {
      const property = schema.properties?.[key];
      if (!property) {
        if (schema.additionalProperties === false) return `${path}.${key}: not in the schema`;
        continue;
      }
      const v = violation(member, property, `${path}.${key}`);
      if (v) return v;
    }
  }
  return null;
}
