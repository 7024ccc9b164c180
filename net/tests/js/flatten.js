// flatten.js — prints an open-dis PDU object as "prefix.path=value" lines, the format the
// C++ interop test (net/tests/test_interop_opendis.cpp) writes for its own structs.
'use strict';

function flatten(value, prefix, out) {
  if (value === null || value === undefined) {
    out.push(prefix + '=null');
  } else if (Array.isArray(value)) {
    value.forEach((v, i) => flatten(v, prefix + '.' + i, out));
  } else if (typeof value === 'object') {
    for (const key of Object.keys(value)) {
      if (typeof value[key] === 'function') continue;
      if (prefix.endsWith('marking') && key === 'characters') continue;  // see marking.text
      flatten(value[key], prefix + '.' + key, out);
    }
    if (typeof value.getMarking === 'function') out.push(prefix + '.text=' + value.getMarking());
  } else if (typeof value === 'number') {
    out.push(prefix + '=' + (Number.isNaN(value) ? 'null' : String(value)));
  } else {
    out.push(prefix + '=' + String(value));
  }
  return out;
}

module.exports = { flatten };
