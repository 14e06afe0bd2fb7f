//! Small reads of the page's document shared by the components.

use wasm_bindgen::JsCast;

/// The element of the page with `id`, as a `T` (`web_sys::Element`, `HtmlElement`,
/// `SvgElement`, …); `None` when there is none or it is not a `T`.
pub fn by_id<T: JsCast>(id: &str) -> Option<T> {
    web_sys::window()?.document()?.get_element_by_id(id)?.dyn_into().ok()
}

/// The number in a text the page wrote or a number or range input holds, as the browser
/// reads it (`Number(text)`): for such decimal texts, the same double Rust's parser gives,
/// without that parser and its 11 KB table of powers in the first load (BENCHMARKS.md).
/// `None` for an empty text or one that is not a number.
pub fn number_of(text: &str) -> Option<f64> {
    let text = text.trim();
    if text.is_empty() {
        return None;
    }
    let Ok(number) = text.parse::<js_sys::Number>();
    let x = number.value_of();
    (!x.is_nan()).then_some(x)
}
