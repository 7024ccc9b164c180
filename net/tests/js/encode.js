// encode.js OUTFILE — encodes one PDU of each type we speak with open-dis 1.3.6 (DIS 7), writes
// them back to back to OUTFILE, and prints the fields it set ("index.path=value" lines) for the
// C++ test to compare with its own decoding. Values are exact in float32 so nothing rounds.
'use strict';
require('open-dis/dist/dis7.min.js');
const fs = require('fs');
const { flatten } = require('./flatten');

function id(pduId, site, app, entity) {
  pduId.siteID = site;
  pduId.applicationID = app;
  pduId.entityID = entity;
}
function vec(v, x, y, z) {
  v.x = x;
  v.y = y;
  v.z = z;
}
function header(pdu, type, family) {
  pdu.protocolVersion = 7;
  pdu.exerciseID = 1;
  pdu.pduType = type;
  pdu.protocolFamily = family;
  pdu.timestamp = 0x0ABCDEF1;
}
function event(e, site, app, number) {
  e.simulationAddress.site = site;
  e.simulationAddress.application = app;
  e.eventNumber = number;
}
function param(recordType, f1, f2, f3, f4) {
  const p = new dis.VariableParameter();
  p.recordType = recordType;
  p.variableParameterFields1 = f1;
  p.variableParameterFields2 = f2;
  p.variableParameterFields3 = f3;
  p.variableParameterFields4 = f4;
  return p;
}

const es = new dis.EntityStatePdu();
header(es, 1, 1);
id(es.entityID, 42, 7, 1001);
es.forceId = 2;
Object.assign(es.entityType, { entityKind: 1, domain: 2, country: 225, category: 1, subcategory: 3, specific: 2, extra: 0 });
Object.assign(es.alternativeEntityType, { entityKind: 1, domain: 2, country: 222, category: 4, subcategory: 0, specific: 0, extra: 0 });
vec(es.entityLinearVelocity, 120.5, -30.25, 4.0);
vec(es.entityLocation, -2707522.125, -4353260.5, 3781450.75);
Object.assign(es.entityOrientation, { psi: 1.25, theta: -0.125, phi: 0.0625 });
es.entityAppearance = 0x00300004;
es.deadReckoningParameters.deadReckoningAlgorithm = 4;
vec(es.deadReckoningParameters.entityLinearAcceleration, 0.5, 0.25, -1.5);
vec(es.deadReckoningParameters.entityAngularVelocity, 0.0, 0.0, 0.1875);
es.marking.characterSet = 1;
es.marking.setMarking('f16-lead');
es.capabilities = 7;
es.variableParameters.push(param(0, 1.5, 4096, 11, 0));
es.variableParameters.push(param(1, -2.0, 1, 2, 3));
es.numberOfVariableParameters = es.variableParameters.length;
es.length = 144 + 16 * es.variableParameters.length;  // open-dis does not compute it

const fire = new dis.FirePdu();
header(fire, 2, 2);
id(fire.firingEntityID, 42, 7, 1001);
id(fire.targetEntityID, 9, 9, 9);
id(fire.munitionExpendibleID, 42, 7, 5000);
event(fire.eventID, 42, 7, 77);
fire.fireMissionIndex = 3;
vec(fire.locationInWorldCoordinates, -2707000.5, -4353000.25, 3781000.125);
Object.assign(fire.descriptor.munitionType, { entityKind: 2, domain: 2, country: 225, category: 2, subcategory: 1, specific: 0, extra: 0 });
Object.assign(fire.descriptor, { warhead: 1000, fuse: 1000, quantity: 1, rate: 0 });
vec(fire.velocity, 300.0, 0.5, -2.0);
fire.range = 2500.0;
fire.length = 96;

const det = new dis.DetonationPdu();
header(det, 3, 2);
id(det.firingEntityID, 42, 7, 1001);
id(det.targetEntityID, 9, 9, 9);
id(det.explodingEntityID, 42, 7, 5000);
event(det.eventID, 42, 7, 77);
vec(det.velocity, 280.0, 0.5, -20.0);
vec(det.locationInWorldCoordinates, -2706000.5, -4352000.25, 3780000.125);
Object.assign(det.descriptor.munitionType, { entityKind: 2, domain: 2, country: 225, category: 2, subcategory: 1, specific: 0, extra: 0 });
Object.assign(det.descriptor, { warhead: 1000, fuse: 1000, quantity: 1, rate: 0 });
vec(det.locationOfEntityCoordinates, 1.0, 2.0, -0.5);
det.detonationResult = 1;
det.variableParameters.push(param(2, 8.0, 5, 6, 7));
det.numberOfVariableParameters = det.variableParameters.length;
det.length = 104 + 16 * det.variableParameters.length;

const col = new dis.CollisionPdu();
header(col, 4, 1);
id(col.issuingEntityID, 42, 7, 1001);
id(col.collidingEntityID, 9, 9, 9);
event(col.eventID, 42, 7, 78);
col.collisionType = 1;
vec(col.velocity, 12.0, -3.5, 0.0);
col.mass = 12000.0;
vec(col.location, 4.0, -1.0, 0.5);
col.length = 60;

const esu = new dis.EntityStateUpdatePdu();
header(esu, 67, 1);
id(esu.entityID, 42, 7, 1001);
vec(esu.entityLinearVelocity, 121.0, -30.0, 4.5);
vec(esu.entityLocation, -2707500.0, -4353250.0, 3781460.0);
Object.assign(esu.entityOrientation, { psi: 1.5, theta: -0.25, phi: 0.125 });
esu.entityAppearance = 0x00300008;
esu.numberOfVariableParameters = 0;
esu.length = 72;

const pdus = [es, fire, det, col, esu];
const chunks = [];
const lines = [];
pdus.forEach((pdu, i) => {
  const out = new dis.OutputStream(new ArrayBuffer(8192));
  pdu.encodeToBinary(out);
  chunks.push(Buffer.from(out.toByteArray()));
  flatten(pdu, String(i), lines);
});
fs.writeFileSync(process.argv[2], Buffer.concat(chunks));
lines.push('count=' + pdus.length);
process.stdout.write(lines.join('\n') + '\n');
