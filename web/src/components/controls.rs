//! The simulation controls: the PROGRAM to run (when the project has several), run,
//! pause, single scan, N scans, restarts, cycle time,
//! speed, and read-outs of the run state, scan count and virtual time, and which version
//! runs when it is not the text on the screen.

use leptos::prelude::*;
use plc_core::sim::SimState;
use plc_core::vm::format_time;

use crate::i18n::{t, tf, K};
use crate::lazy::{self, lazy_view, What};
use crate::state::{version_text, AppState, RunMode, Speed};

/// The control bar of the simulation pane.
#[component]
pub fn Controls() -> impl IntoView {
    let state = expect_context::<AppState>();
    let mode = state.run_mode;
    let has_sim = move || state.with_sim(|_| ()).is_some();
    let faulted =
        move || state.with_sim(|s| matches!(s.state(), SimState::Faulted(_))).unwrap_or(false);
    // With errors the buttons stay enabled: pressing one says what to fix (and offers the
    // last version that built) instead of silently running an older build.
    let has_errors = move || state.diagnostics.with(|ds| ds.iter().any(|d| d.error));
    // While the engine loads, Run and Step are offered: they are done once it is here.
    let can_scan = move || (!state.engine_ready.get() || has_sim() || has_errors()) && !faulted();
    let version = move || version_text(state.stale.get(), mode.get()).unwrap_or_default();
    let running = move || mode.get() == RunMode::Running;
    let scans_per_step = RwSignal::new(10u64);
    // Once shown, the slider's row stays while there is a program (a rebuild starts a new
    // recording at scan 0): the panels below never jump while the student types or clicks.
    let has_history = Memo::new(move |was: Option<&bool>| {
        let range = state.recorded_range();
        range.is_some_and(|(first, last)| last > first)
            || (was.copied().unwrap_or(false) && range.is_some())
    });

    let status = move || {
        if !state.engine_ready.get() {
            (t(K::sim_loading), "status status-stopped")
        } else if !has_sim() {
            (t(K::sim_no_program), "status status-stopped")
        } else if faulted() {
            (t(K::sim_fault), "status status-fault")
        } else {
            match mode.get() {
                RunMode::Running => (t(K::sim_running), "status status-running"),
                RunMode::Paused => (t(K::sim_paused), "status status-paused"),
                RunMode::Stopped => (t(K::sim_stopped), "status status-stopped"),
            }
        }
    };
    let scans = move || state.with_readout(|s| s.scan_count()).unwrap_or(0).to_string();
    let time = move || state.with_readout(|s| format_time(s.time_ns())).unwrap_or_default();
    let cycle = move || state.project.with(|p| p.settings.cycle_ms).to_string();
    let speed_value = move || match state.speed.get() {
        Speed::RealTime => "1",
        Speed::Times10 => "10",
        Speed::Max => "max",
    };

    view! {
        <section class="panel controls" aria-label=t(K::sim_controls)>
            <h2>{t(K::sim_simulation)}</h2>
            <div class="control-row">
                <button class="primary" disabled=move || !can_scan() || running()
                    on:click=move |_| state.run()>{t(K::sim_run)}</button>
                <button disabled=move || !running() on:click=move |_| state.pause()>{t(K::sim_pause)}</button>
                <button disabled=move || running() || !state.can_step_back()
                    title=t(K::sim_step_back_title)
                    on:click=move |_| state.step_back()>{t(K::sim_step_back)}</button>
                <button data-tour="step" disabled=move || !can_scan() on:click=move |_| state.step(1)>{t(K::sim_step)}</button>
                <button disabled=move || !has_sim() on:click=move |_| state.reset()>{t(K::sim_reset)}</button>
                <button disabled=move || !has_sim() on:click=move |_| state.warm_restart()>
                    {t(K::sim_warm_restart)}
                </button>
            </div>
            {move || {
                let names = state.programs.get();
                (names.len() > 1).then(|| {
                    let running = state.running.get().unwrap_or_default();
                    view! {
                        <div class="control-row">
                            <label class="field">
                                <span>{t(K::sim_program)}</span>
                                <select aria-label=t(K::sim_program_to_run) title=t(K::sim_program_title)
                                    on:change=move |ev| state.set_program(&event_target_value(&ev))>
                                    {names.into_iter().map(|n| {
                                        let selected = n.eq_ignore_ascii_case(&running);
                                        view! { <option value=n.clone() selected=selected>{n.clone()}</option> }
                                    }).collect_view()}
                                </select>
                            </label>
                        </div>
                    }
                })
            }}
            <div class="control-row">
                <label class="field">
                    <span>{t(K::sim_scans_per_step)}</span>
                    <input type="number" min="1" max="1000000" class="num"
                        prop:value=move || scans_per_step.get().to_string()
                        on:change=move |ev| {
                            let n = event_target_value(&ev).trim().parse::<u64>().unwrap_or(1);
                            scans_per_step.set(n.clamp(1, 1_000_000));
                        }/>
                </label>
                <button disabled=move || !can_scan()
                    on:click=move |_| state.step(scans_per_step.get_untracked())>{t(K::sim_step_n)}</button>
                <label class="field">
                    <span>{t(K::sim_cycle_time)}</span>
                    <input type="number" min="1" max="60000" class="num" prop:value=cycle
                        on:change=move |ev| {
                            match event_target_value(&ev).trim().parse::<u64>() {
                                Ok(ms) => state.set_cycle_ms(ms),
                                Err(_) => state.error(t(K::sim_cycle_time_invalid)),
                            }
                        }/>
                </label>
                <label class="field">
                    <span>{t(K::sim_speed)}</span>
                    <select prop:value=speed_value on:change=move |ev| {
                        let speed = match event_target_value(&ev).as_str() {
                            "10" => Speed::Times10,
                            "max" => Speed::Max,
                            _ => Speed::RealTime,
                        };
                        state.speed.set(speed);
                    }>
                        <option value="1" selected=move || speed_value() == "1">{t(K::sim_real_time)}</option>
                        <option value="10" selected=move || speed_value() == "10">"×10"</option>
                        <option value="max" selected=move || speed_value() == "max">{t(K::sim_as_fast_as_possible)}</option>
                    </select>
                </label>
            </div>
            // The slider and the banner are a chunk of their own (`lazy::recorded_view`),
            // fetched once the recording holds a scan to go back to.
            // Its room is kept while there is a program, so pressing Run (which starts the
            // recording) never moves the inputs below under the pointer.
            <div class="recorded-slot" class:reserved=has_sim>
                {move || has_history.get().then(|| lazy_view(What::Recording, lazy::recorded_view))}
            </div>
            <div class="readouts">
                <span class=move || status().1 role="status" aria-label=move || tf(K::sim_plc_state, &[("state", status().0)])>
                    {move || status().0}
                </span>
                <span class="readout">{t(K::sim_scan)} <output aria-label=t(K::sim_scan_count)>{scans}</output></span>
                <span class="readout">{t(K::sim_time)} <output aria-label=t(K::sim_virtual_time)>{time}</output></span>
            </div>
            <p class="run-version" role="status" aria-live="polite">{version}</p>
        </section>
    }
}
