//! Downloads of generated text files (Blob + object URL + a temporary link).

use wasm_bindgen::{JsCast, JsValue};

use crate::i18n::{tf, K};

/// Offers `text` as a file named `name` of type `mime`; returns an error text on failure.
pub fn download(name: &str, mime: &str, text: &str) -> Result<(), String> {
    download_parts(name, mime, &JsValue::from_str(text))
}

/// Offers `part` (a string, or bytes as a `Uint8Array`) as a file named `name`.
pub fn download_parts(name: &str, mime: &str, part: &JsValue) -> Result<(), String> {
    let fail =
        |e: JsValue| tf(K::state_download_failed, &[("name", name), ("error", &format!("{e:?}"))]);
    let window = web_sys::window().ok_or("no window")?;
    let document = window.document().ok_or("no document")?;
    let parts = js_sys::Array::of1(part);
    let opts = web_sys::BlobPropertyBag::new();
    opts.set_type(mime);
    let blob = web_sys::Blob::new_with_str_sequence_and_options(&parts, &opts).map_err(fail)?;
    let url = web_sys::Url::create_object_url_with_blob(&blob).map_err(fail)?;
    let a = document
        .create_element("a")
        .map_err(fail)?
        .dyn_into::<web_sys::HtmlAnchorElement>()
        .map_err(|_| tf(K::state_download_failed_short, &[("name", name)]))?;

    a.set_href(&url);
    a.set_download(name);
    a.set_attribute("style", "display:none").map_err(fail)?;
    if let Some(body) = document.body() {
        let _ = body.append_child(&a);
        a.click();
        let _ = body.remove_child(&a);
    } else {
        a.click();
    }
    // Revoked later: some browsers start reading the URL after `click` returns.
    leptos::prelude::set_timeout(
        move || {
            let _ = web_sys::Url::revoke_object_url(&url);
        },
        std::time::Duration::from_secs(30),
    );
    Ok(())
}
