//! A link to copy: the read-only box that shows a share link (selected when focused) with
//! its close button, and copying text to the clipboard. The project's Share and an
//! exercise's Share exercise both use them.

use leptos::ev;
use leptos::prelude::*;
use wasm_bindgen::JsCast;
use wasm_bindgen_futures::JsFuture;

/// Copies `text` to the clipboard; false when the page may not.
pub async fn copy_to_clipboard(text: &str) -> bool {
    match web_sys::window() {
        Some(w) => JsFuture::from(w.navigator().clipboard().write_text(text)).await.is_ok(),
        None => false,
    }
}

/// The box showing `link` (named `label`), closed by the button named `close_label`.
#[component]
pub fn ShareBox(
    link: String,
    label: &'static str,
    close_label: &'static str,
    on_close: impl Fn() + 'static,
) -> impl IntoView {
    view! {
        <div class="share-box">
            <input type="text" readonly aria-label=label prop:value=link
                on:focus=move |e: ev::FocusEvent| {
                    if let Some(i) = e.target().and_then(|t| t.dyn_into::<web_sys::HtmlInputElement>().ok()) {
                        i.select();
                    }
                }/>
            <button class="close" aria-label=close_label on:click=move |_| on_close()>"×"</button>
        </div>
    }
}
