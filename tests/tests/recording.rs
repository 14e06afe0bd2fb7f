//! Recording and replay (issue 36) on random programs: whatever a program does and
//! whatever is written, held and forced from outside between its scans, every recorded scan
//! is rebuilt bit for bit from the recording, and rewinding to one gives back that state.
//! The programs come from the fuzz grammar (`plc_tests::fuzz::program_from_bytes`).
#![cfg(not(target_arch = "wasm32"))]

use plc_core::sim::{ScanOutcome, Simulator};
use plc_core::vm::TraceEvent;
use plc_tests::fuzz::program_from_bytes;
use proptest::prelude::*;

fn simulator(source: &str) -> Option<Simulator> {
    let analysis = plc_core::semantic::analyze(source);
    if analysis.diagnostics.iter().any(|d| d.is_error()) {
        return None;
    }
    let program = analysis.program?;
    let main = program.programs().find(|&p| !program.pou(p).library)?;
    Simulator::new(program, main).ok()
}

/// One change from outside between two scans, chosen by a byte.
fn poke(sim: &mut Simulator, b: u8) {
    let value = i32::from(b % 50) - 20;
    let _ = match b % 9 {
        0 => sim.write("i", &value.to_string()),
        1 => sim.hold("j", &value.to_string()),
        2 => {
            sim.release("j");
            Ok(())
        }
        3 => sim.force("b", if b.is_multiple_of(2) { "TRUE" } else { "FALSE" }),
        4 => {
            sim.unforce("b");
            Ok(())
        }
        5 => {
            sim.set_cycle_ns(i64::from(1 + b % 20) * 1_000_000);
            Ok(())
        }
        6 => sim.write("s", "'xyz'"),
        _ => Ok(()),
    };
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, .. ProptestConfig::default() })]

    #[test]
    fn every_recorded_scan_is_rebuilt_bit_for_bit(
        program in proptest::collection::vec(any::<u8>(), 8..120),
        script in proptest::collection::vec(any::<u8>(), 40..90),
        rewind_at in any::<u8>(),
    ) {
        let source = program_from_bytes(&program);
        let Some(mut sim) = simulator(&source) else { return Ok(()) };
        sim.set_recording(true).expect("a small image records");
        let mut live = vec![sim.state_memory().to_vec()];
        let mut vars = vec![sim.vars_json()];
        for &b in &script {
            if b.is_multiple_of(3) {
                poke(&mut sim, b / 3);
            }
            if let ScanOutcome::Fault(_) = sim.scan() {
                break;
            }
            live.push(sim.state_memory().to_vec());
            vars.push(sim.vars_json());
        }
        let (first, last) = sim.recorded_range().expect("recording");
        prop_assert_eq!((first, last), (0, live.len() as u64 - 1));
        for k in first..=last {
            let view = sim.view_at(k).expect("recorded");
            prop_assert_eq!(view.state_memory(), &live[k as usize][..], "scan {} of\n{}", k, source);
            prop_assert_eq!(&view.vars_json(), &vars[k as usize]);
        }
        // A traced replay logs every write: applied to the state before, they give the
        // state after, cell for cell.
        if last > 0 {
            let k = 1 + u64::from(rewind_at) % last;
            let traced = sim.trace_scan(k).expect("recorded");
            prop_assert_eq!(traced.view.state_memory(), &live[k as usize][..]);
            let mut cells = traced.before.clone();
            for e in &traced.events {
                if let TraceEvent::Store { addr, value, .. } | TraceEvent::External { addr, value, .. } = *e {
                    if let Some(c) = cells.get_mut(addr as usize) {
                        *c = value;
                    }
                }
            }
            prop_assert_eq!(&cells[..live[k as usize].len()], &live[k as usize][..], "scan {} of\n{}", k, source);
        }
        let k = u64::from(rewind_at) % (last + 1);
        sim.rewind_to(k).expect("recorded");
        prop_assert_eq!(sim.scan_count(), k);
        prop_assert_eq!(sim.state_memory(), &live[k as usize][..]);
        prop_assert_eq!(sim.recorded_range(), Some((0, k)));
    }
}
