// decode.js FILE — decodes the PDUs written back to back in FILE (each header's length field
// says where the next begins) with open-dis 1.3.6 (DIS 7) and prints every field, one
// "index.path=value" line each, for the C++ test to compare with what it encoded.
'use strict';
require('open-dis/dist/dis7.min.js');  // declares the global `dis`
const fs = require('fs');
const { flatten } = require('./flatten');

const bytes = fs.readFileSync(process.argv[2]);
const factory = new dis.PduFactory();
const lines = [];
let offset = 0;
let index = 0;
while (offset + 12 <= bytes.length) {
  const length = bytes.readUInt16BE(offset + 8);
  if (length < 12 || offset + length > bytes.length) {
    console.error(`bad length ${length} at offset ${offset}`);
    process.exit(2);
  }
  // open-dis wants an ArrayBuffer holding exactly this PDU.
  const ab = bytes.buffer.slice(bytes.byteOffset + offset, bytes.byteOffset + offset + length);
  const pdu = factory.createPdu(ab);
  flatten(pdu, String(index), lines);
  offset += length;
  index += 1;
}
lines.push('count=' + index);
process.stdout.write(lines.join('\n') + '\n');
