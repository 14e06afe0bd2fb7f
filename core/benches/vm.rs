//! Criterion benchmarks of B1, B2, B3, B4 and B6 (see BENCHMARKS.md), on the same programs
//! and work as `plc bench` (`plc_core::bench`), for statistics across runs:
//! `cargo bench -p plc-core --bench vm [-- FILTER]`. B5 (one long run of a virtual hour)
//! stays with `plc bench` and the browser harness.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use plc_core::bench::workload::{check_and_compile, load, scan};
use plc_core::bench::{ladder, programs};
use plc_core::sim::Simulator;

fn loaded(source: &str) -> Simulator {
    load(source).unwrap_or_else(|e| panic!("{e}"))
}

fn one_scan(sim: &mut Simulator) {
    scan(sim).unwrap_or_else(|e| panic!("{e}"));
}

/// B1 and B2: the VM and the hand-written Rust, side by side.
fn paired(c: &mut Criterion) {
    let mut g = c.benchmark_group("B1");
    let mut sim = loaded(&programs::b1(100_000));
    g.bench_function("vm", |b| b.iter(|| one_scan(&mut sim)));
    g.bench_function("native", |b| b.iter(|| programs::b1_native(black_box(100_000))));
    g.finish();

    let mut g = c.benchmark_group("B2");
    g.sample_size(10);
    let mut sim = loaded(&programs::b2(1_000));
    g.bench_function("vm", |b| b.iter(|| one_scan(&mut sim)));
    g.bench_function("native", |b| b.iter(|| programs::b2_native(black_box(1_000))));
    g.finish();
}

/// B3: one scan of the CASE OF code generated from Petri net cycles of 10 … 10,000 places.
fn case_of(c: &mut Criterion) {
    let mut g = c.benchmark_group("B3");
    for places in [10, 100, 1_000, 10_000] {
        let source = programs::b3(places).unwrap_or_else(|e| panic!("{e}"));
        let mut sim = loaded(&source);
        sim.hold("Go", "TRUE").unwrap_or_else(|e| panic!("{e}"));
        g.bench_with_input(BenchmarkId::from_parameter(places), &places, |b, _| {
            b.iter(|| one_scan(&mut sim))
        });
    }
    g.finish();
}

/// B4: one scan of 1,000 ladder rungs × 10 elements (throughput in elements).
fn ladder_rungs(c: &mut Criterion) {
    let rungs = 1_000;
    let project = ladder::project(rungs);
    let mut sim = plc_core::run::project_simulator(&project, None)
        .unwrap_or_else(|d| panic!("{:?}", d.first().map(|d| &d.message)));
    for i in (1..ladder::INPUTS).step_by(3) {
        sim.hold(&format!("I{i}"), "TRUE").unwrap_or_else(|e| panic!("{e}"));
    }
    let mut g = c.benchmark_group("B4");
    g.throughput(Throughput::Elements((rungs * ladder::ELEMENTS_PER_RUNG) as u64));
    g.bench_function("scan", |b| b.iter(|| one_scan(&mut sim)));
    g.finish();
}

/// B6: check + compile of the generated 5,000-line program.
fn check_compile(c: &mut Criterion) {
    let source = programs::b6(5_000);
    let mut g = c.benchmark_group("B6");
    g.sample_size(20);
    g.bench_function("check_and_compile", |b| {
        b.iter(|| check_and_compile(black_box(&source)).unwrap_or_else(|e| panic!("{e}")))
    });
    g.finish();
}

criterion_group!(benches, paired, case_of, ladder_rungs, check_compile);
criterion_main!(benches);
