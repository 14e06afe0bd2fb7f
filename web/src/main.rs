//! The PLC trainer's browser app: a Leptos (CSR) single-page app around `plc-core`.

mod app;
mod components;
mod examples;
mod state;
mod storage;

fn main() {
    console_error_panic_hook::set_once();
    leptos::mount::mount_to_body(app::App);
}
