// Decodes quantized-mesh tiles with @here/quantized-mesh-decoder (pinned in
// package-lock.json), an implementation independent of locator's encoder,
// and prints what it read as text for quantized_mesh_decoder_test.cc:
//
//   tile <file>
//   header <centreX> <centreY> <centreZ> <minHeight> <maxHeight>
//          <sphereX> <sphereY> <sphereZ> <radius> <occlusionX> <Y> <Z>
//   vertices <n>            then n lines "<u> <v> <height>" (0..32767)
//   triangles <m>           then m lines "<a> <b> <c>"
//   west|south|east|north <k> <index>...
//
// A file the decoder cannot read ends the program with status 1.
//
// Usage: node decode_tiles.js FILE...

'use strict';

const fs = require('fs');
const path = require('path');
const decode = require(path.join(__dirname, 'node_modules', '@here',
                                 'quantized-mesh-decoder')).default;

const lines = [];
for (const file of process.argv.slice(2)) {
  const bytes = fs.readFileSync(file);
  const buffer =
      bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.length);
  const tile = decode(buffer);
  const h = tile.header;
  lines.push('tile ' + file);
  lines.push(['header', h.centerX, h.centerY, h.centerZ, h.minHeight,
              h.maxHeight, h.boundingSphereCenterX, h.boundingSphereCenterY,
              h.boundingSphereCenterZ, h.boundingSphereRadius,
              h.horizonOcclusionPointX, h.horizonOcclusionPointY,
              h.horizonOcclusionPointZ].join(' '));
  const n = tile.vertexData.length / 3;
  lines.push('vertices ' + n);
  for (let i = 0; i < n; ++i) {
    lines.push(tile.vertexData[i] + ' ' + tile.vertexData[i + n] + ' ' +
               tile.vertexData[i + 2 * n]);
  }
  const m = tile.triangleIndices.length / 3;
  lines.push('triangles ' + m);
  for (let i = 0; i < m; ++i) {
    lines.push(tile.triangleIndices[3 * i] + ' ' +
               tile.triangleIndices[3 * i + 1] + ' ' +
               tile.triangleIndices[3 * i + 2]);
  }
  for (const side of ['west', 'south', 'east', 'north']) {
    const indices = Array.from(tile[side + 'Indices']);
    lines.push([side, indices.length].concat(indices).join(' '));
  }
}
process.stdout.write(lines.join('\n') + '\n');
