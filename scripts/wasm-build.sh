# Sourced by scripts/build-web.sh and scripts/bench-browser.sh, so that the benchmark
# module is built exactly as the site is: the same cargo profile and flags, and the same
# wasm-opt pass over the result.

# The flags of every wasm32 build (.cargo/config.toml) plus the relocations wasm-split reads
# (they change nothing in the code; the benchmark builds with them too, so both builds share
# the compiled plc-core).
export CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="--cfg erase_components -C link-args=--emit-relocs"
# The site's cargo profile (Cargo.toml: size for the UI, speed for the engine).
WASM_PROFILE=wasm-release

# wasm-opt as the site uses it: IN OUT. (wasm-split writes a name subsection wasm-opt
# does not know and warns about; the names are dropped anyway.)
wasm_opt() {
  wasm-opt -Oz --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext \
    --enable-mutable-globals --enable-reference-types --enable-multivalue "$1" -o "$2" \
    2> >(grep -v 'unknown name subsection' >&2)
}
