//! The PLC trainer's browser app: a Leptos (CSR) single-page app around `plc-core`.

mod app;
mod components;
mod download;
mod examples;
mod exercises;
mod import;
mod state;
mod storage;

fn main() {
    std::panic::set_hook(Box::new(|info| {
        state::note_panic();
        console_error_panic_hook::hook(info);
    }));
    leptos::mount::mount_to_body(app::App);
}
