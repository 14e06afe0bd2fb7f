# Sourced by scripts/build-web.sh and scripts/bench-browser.sh, so that the benchmark
# module is built exactly as the site is: the same cargo profile and flags, and the same
# wasm-opt pass over the result.

# The flags of every wasm32 build (.cargo/config.toml) plus the relocations wasm-split reads
# (they change nothing in the code; the benchmark builds with them too, so both builds share
# the compiled plc-core).
# Source paths are written into the module (panic locations), so the size of the site would
# depend on where the clone and the cargo home are: a CI clone under a longer path was 4 KB
# over the budget a shorter one met. Mapping them to short fixed prefixes makes the build the
# same bytes wherever it runs.
wasm_path_remaps="--remap-path-prefix=$PWD=. --remap-path-prefix=${CARGO_HOME:-$HOME/.cargo}=~cargo"
for src in "${CARGO_HOME:-$HOME/.cargo}"/registry/src/*/; do
  [ -d "$src" ] && wasm_path_remaps+=" --remap-path-prefix=${src%/}=~"
done
for rust_src in "$(rustc --print sysroot)"/lib/rustlib/src/rust; do
  [ -d "$rust_src" ] && wasm_path_remaps+=" --remap-path-prefix=$rust_src=~rust"
done
# The standard library is built with the app (cargo's build-std) rather than taken prebuilt:
# at the profile's opt-level z (the prebuilt one is compiled for speed), with its
# `optimize_for_size` code, and with panics that trap at once (`-Cpanic=immediate-abort`: no
# message formatting, no table of source locations). A panic is a bug (no user input may
# cause one) and stopped the page before too (wasm has no unwinding); now it does so without
# a message on the console, and web/boot.js tells the page it stopped. These are unstable
# options of the stable compiler: `wasm_cargo` allows them (RUSTC_BOOTSTRAP=1) for its own
# cargo run only (the compiler then takes itself for a nightly one, whose default symbol
# names scripts/site.mjs cannot read: `legacy` keeps the names it checks the first load by);
# build-std needs the rust-src component (scripts/setup.sh). What each saves:
# BENCHMARKS.md, "The standard library built with the app".
# `--cfg plc_speed` compiles the scan loop's functions for speed (core/src/lib.rs).
export CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="--cfg erase_components --cfg plc_speed -C link-args=--emit-relocs $wasm_path_remaps -Zunstable-options -Cpanic=immediate-abort -Csymbol-mangling-version=legacy"
# cargo for the site's wasm: `wasm_cargo build --target wasm32-unknown-unknown …`.
wasm_cargo() {
  RUSTC_BOOTSTRAP=1 cargo "$@" -Zbuild-std=std,panic_abort -Zbuild-std-features=optimize_for_size
}
# The site's cargo profile (Cargo.toml: size for the UI, speed for the engine).
WASM_PROFILE=wasm-release
# To measure the engine at another opt-level (BENCHMARKS.md, "The engine at speed"), set
# WASM_CORE_OPT_LEVEL (z, s, 1, 2 or 3): plc-core is then built at that level, the rest as
# the profile says. Pass "${wasm_cargo_flags[@]}" to cargo.
wasm_cargo_flags=()
if [ -n "${WASM_CORE_OPT_LEVEL:-}" ]; then
  case "$WASM_CORE_OPT_LEVEL" in
    z | s) level="\"$WASM_CORE_OPT_LEVEL\"" ;;
    [0-3]) level=$WASM_CORE_OPT_LEVEL ;;
    *) echo "WASM_CORE_OPT_LEVEL is z, s, 0, 1, 2 or 3, not '$WASM_CORE_OPT_LEVEL'" >&2; exit 1 ;;
  esac
  wasm_cargo_flags=(--config "profile.$WASM_PROFILE.package.plc-core.opt-level=$level")
fi

# wasm-opt as the site uses it: IN OUT. (wasm-split writes a name subsection wasm-opt
# does not know and warns about; the names are dropped anyway.)
# --low-memory-unused: the module never uses the lowest 1 KB of memory (Rust lays the
# 1 MB stack out first, growing down towards 0, and the data after it, at 1 MB: that KB is
# reached only by a stack 1023 KB deep), so wasm-opt may fold small constant offsets into
# loads and stores; 3 KB less to download (gzip).
# -ocimfs=50: a function with one caller is inlined into it only when small. By default
# wasm-opt inlines every such function, which made the VM's `Machine::run` 35 KB, which
# V8's optimising compiler took 75-100 ms to compile while B5 ran it unoptimised
# (BENCHMARKS.md, B5 in Chromium); the module is no larger.
wasm_opt() {
  wasm-opt -Oz -ocimfs=50 --low-memory-unused --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext \
    --enable-mutable-globals --enable-reference-types --enable-multivalue "$1" -o "$2" \
    2> >(grep -v 'unknown name subsection' >&2)
}
