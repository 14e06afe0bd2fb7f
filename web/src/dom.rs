//! Small reads of the page's document shared by the components.

use wasm_bindgen::JsCast;

/// The element of the page with `id`, as a `T` (`web_sys::Element`, `HtmlElement`,
/// `SvgElement`, …); `None` when there is none or it is not a `T`.
pub fn by_id<T: JsCast>(id: &str) -> Option<T> {
    web_sys::window()?.document()?.get_element_by_id(id)?.dyn_into().ok()
}
