// Reads the CSV files of `sdlqr-logger export` (RFC 4180; header cells "name[i] [unit]"; a
// variable-length array is one cell holding a JSON array) and compares a message decoded from
// JSON (Foxglove, MCAP) with its row, field by field.
import { readFileSync } from 'node:fs';

export function parseCsv(text) {
  const rows = [];
  let row = [], cell = '', quoted = false;
  for (let i = 0; i < text.length; i++) {
    const c = text[i];
    if (quoted) {
      if (c === '"' && text[i + 1] === '"') { cell += '"'; i++; } else if (c === '"') quoted = false; else cell += c;
    } else if (c === '"') quoted = true;
    else if (c === ',') { row.push(cell); cell = ''; } else if (c === '\n') { row.push(cell); rows.push(row); row = []; cell = ''; } else cell += c;
  }
  if (cell !== '' || row.length) { row.push(cell); rows.push(row); }
  return rows;
}

// A message's identity: its seq and utime, and on HEARTBEAT (one channel, many publishers) its process.
export const messageKey = (m) => `${m.seq}|${m.utime}|${m.process ?? ''}`;

// {columns: ["utime", "position[0]", ...], rows: [[...cells]], byKey: Map(messageKey -> row)}
export function readExportCsv(path) {
  const [header, ...rows] = parseCsv(readFileSync(path, 'utf8'));
  const columns = header.map((h) => h.replace(/ \[[^\]]*\]$/, ''));
  const [seq, utime, process] = ['seq', 'utime', 'process'].map((c) => columns.indexOf(c));
  const byKey = new Map(rows.map((r) => [`${r[seq]}|${r[utime]}|${process < 0 ? '' : r[process]}`, r]));
  return { columns, rows, byKey, column: (name) => columns.indexOf(name) };
}

function sameNumber(cell, value) {
  if (value === null) return ['nan', 'inf', '-inf'].includes(cell);
  return Number(cell) === value;
}

function jsonCellValue(cell) {
  return JSON.parse(cell.replace(/-?Infinity|NaN/g, 'null'));
}

// The first column whose cell differs from the message's value, or null when all agree.
export function rowDifference(csv, row, message) {
  for (let i = 0; i < csv.columns.length; i++) {
    const name = csv.columns[i];
    const fixed = name.match(/^(\w+)\[(\d+)\]$/);
    const variable = name.match(/^(\w+)\[([A-Za-z_]\w*)\]$/);
    if (variable) {
      if (JSON.stringify(jsonCellValue(row[i])) !== JSON.stringify(message[variable[1]])) return name;
      continue;
    }
    const value = fixed ? message[fixed[1]]?.[Number(fixed[2])] : message[name];
    if (typeof value === 'string' ? value !== row[i] : !sameNumber(row[i], value)) return `${name}: csv ${row[i]}, json ${value}`;
  }
  return null;
}
