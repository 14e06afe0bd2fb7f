//! The browser's local storage as a [`StorageBackend`] for the core's project store.

use plc_core::project::{StorageBackend, StoreError};
use wasm_bindgen::JsCast;

use crate::i18n::{t, K};

/// `window.localStorage`, mapped to the core's storage trait.
pub struct LocalStorage {
    storage: Option<web_sys::Storage>,
}

impl LocalStorage {
    /// Opens local storage (absent storage makes every call fail with `Unavailable`).
    pub fn open() -> Self {
        let storage = web_sys::window().and_then(|w| w.local_storage().ok().flatten());
        LocalStorage { storage }
    }

    fn storage(&self) -> Result<&web_sys::Storage, StoreError> {
        self.storage
            .as_ref()
            .ok_or_else(|| StoreError::Unavailable(t(K::state_storage_disabled).into()))
    }
}

fn js_error(e: wasm_bindgen::JsValue) -> StoreError {
    match e.dyn_ref::<web_sys::DomException>() {
        Some(d) if d.name() == "QuotaExceededError" || d.code() == 22 => StoreError::QuotaExceeded,
        Some(d) => StoreError::Unavailable(d.message()),
        None => StoreError::Unavailable(format!("{e:?}")),
    }
}

impl StorageBackend for LocalStorage {
    fn get(&self, key: &str) -> Result<Option<String>, StoreError> {
        self.storage()?.get_item(key).map_err(js_error)
    }

    fn set(&mut self, key: &str, value: &str) -> Result<(), StoreError> {
        self.storage()?.set_item(key, value).map_err(js_error)
    }

    fn remove(&mut self, key: &str) -> Result<(), StoreError> {
        self.storage()?.remove_item(key).map_err(js_error)
    }

    fn keys(&self) -> Result<Vec<String>, StoreError> {
        let storage = self.storage()?;
        let n = storage.length().map_err(js_error)?;
        let mut keys = Vec::with_capacity(n as usize);
        for i in 0..n {
            if let Some(key) = storage.key(i).map_err(js_error)? {
                keys.push(key);
            }
        }
        Ok(keys)
    }
}
