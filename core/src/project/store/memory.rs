//! An in-memory storage backend with an optional quota, for tests.

use std::collections::BTreeMap;

use super::{StorageBackend, StoreError};

/// An in-memory backend with an optional quota in bytes (for tests).
#[derive(Debug, Default, Clone)]
pub struct MemoryBackend {
    map: BTreeMap<String, String>,
    quota: Option<usize>,
}

impl MemoryBackend {
    /// An empty backend that holds at most `quota` bytes of keys and values.
    pub fn with_quota(quota: usize) -> Self {
        MemoryBackend { map: BTreeMap::new(), quota: Some(quota) }
    }

    /// Changes the quota (`None`: unlimited).
    pub fn set_quota(&mut self, quota: Option<usize>) {
        self.quota = quota;
    }

    /// Bytes of keys and values stored.
    pub fn used(&self) -> usize {
        self.map.iter().map(|(k, v)| k.len() + v.len()).sum()
    }

    /// Every key and value (for tests that compare storage before and after).
    pub fn entries(&self) -> &BTreeMap<String, String> {
        &self.map
    }
}

impl StorageBackend for MemoryBackend {
    fn get(&self, key: &str) -> Result<Option<String>, StoreError> {
        Ok(self.map.get(key).cloned())
    }

    fn set(&mut self, key: &str, value: &str) -> Result<(), StoreError> {
        if let Some(q) = self.quota {
            let old = self.map.get(key).map_or(0, |v| key.len() + v.len());
            if self.used() - old + key.len() + value.len() > q {
                return Err(StoreError::QuotaExceeded);
            }
        }
        self.map.insert(key.to_string(), value.to_string());
        Ok(())
    }

    fn remove(&mut self, key: &str) -> Result<(), StoreError> {
        self.map.remove(key);
        Ok(())
    }

    fn keys(&self) -> Result<Vec<String>, StoreError> {
        Ok(self.map.keys().cloned().collect())
    }
}
