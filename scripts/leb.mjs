// LEB128, as the wasm binary format writes its counts and sizes: shared by the build's
// scripts that read or write wasm modules (scripts/pack.mjs, scripts/minify-imports.mjs).

/** `n` (a non-negative integer) as unsigned LEB128. */
export function leb(n) {
  const out = [];
  do {
    let byte = n & 0x7f;
    n = Math.floor(n / 128);
    if (n) byte |= 0x80;
    out.push(byte);
  } while (n);
  return Buffer.from(out);
}

/** The unsigned LEB128 at `at` in `bytes`: [value, the offset after it]. */
export function readLeb(bytes, at) {
  let value = 0;
  let shift = 0;
  let byte;
  do {
    byte = bytes[at++];
    value += (byte & 0x7f) * 2 ** shift;
    shift += 7;
  } while (byte & 0x80);
  return [value, at];
}
