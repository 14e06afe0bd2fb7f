//! The PLC trainer's browser app: a Leptos (CSR) single-page app around `plc-core`.

mod app;
mod components;
mod dom;
mod download;
mod examples;
mod exercises;
mod i18n;
mod import;
mod lazy;
mod state;
mod storage;
mod workers;

fn main() {
    // In a worker (`worker.js` runs this module too) there is no page to draw:
    // `workers::worker_main` starts the worker's own code.
    if web_sys::window().is_none() {
        return;
    }
    std::panic::set_hook(Box::new(|info| {
        state::note_panic();
        console_error_panic_hook::hook(info);
    }));
    // The chosen theme before the first paint of the app, so it never flashes light.
    components::theme::apply(components::theme::stored());
    // A page opening in Polish or Czech fetches its words first (English is built in).
    if i18n::needs_preparing() {
        wasm_bindgen_futures::spawn_local(async {
            i18n::prepare().await;
            leptos::mount::mount_to_body(app::App);
        });
    } else {
        leptos::mount::mount_to_body(app::App);
    }
}
