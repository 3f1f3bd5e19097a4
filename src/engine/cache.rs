//! The in-memory node cache: bounded by bytes, least recently used entries evicted first.

use crate::scene::graph::{NodeKey, NodeResult};
use std::collections::HashMap;
use std::sync::Arc;

/// Default budget of the in-memory cache: 1 GiB.
pub const DEFAULT_BUDGET: usize = 1 << 30;

struct Entry {
    result: Arc<NodeResult>,
    bytes: usize,
    last_use: u64,
}

/// Completed node results by key, at most `budget` bytes in all (as counted by
/// [`NodeResult::bytes`]). Every insert trims least recently used entries until the total fits;
/// a result larger than the whole budget is not kept.
pub struct MemoryCache {
    map: HashMap<NodeKey, Entry>,
    bytes: usize,
    budget: usize,
    tick: u64,
}

impl MemoryCache {
    /// An empty cache holding at most `budget` bytes.
    pub fn new(budget: usize) -> Self {
        MemoryCache {
            map: HashMap::new(),
            bytes: 0,
            budget,
            tick: 0,
        }
    }

    /// The cached result of `key`, marking it as used now.
    pub fn get(&mut self, key: &NodeKey) -> Option<Arc<NodeResult>> {
        self.tick += 1;
        let tick = self.tick;
        let e = self.map.get_mut(key)?;
        e.last_use = tick;
        Some(e.result.clone())
    }

    /// The cached result of `key` without marking it used.
    pub fn peek(&self, key: &NodeKey) -> Option<Arc<NodeResult>> {
        self.map.get(key).map(|e| e.result.clone())
    }

    /// Keeps `result` under `key` (replacing an older one) and trims to the budget.
    pub fn insert(&mut self, key: NodeKey, result: Arc<NodeResult>) {
        let bytes = result.bytes();
        if let Some(old) = self.map.remove(&key) {
            self.bytes -= old.bytes;
        }
        if bytes > self.budget {
            return;
        }
        self.tick += 1;
        self.map.insert(
            key,
            Entry {
                result,
                bytes,
                last_use: self.tick,
            },
        );
        self.bytes += bytes;
        self.trim();
    }

    /// Evicts least recently used entries until the total is within the budget.
    pub fn trim(&mut self) {
        while self.bytes > self.budget {
            let Some(oldest) = self
                .map
                .iter()
                .min_by_key(|(_, e)| e.last_use)
                .map(|(k, _)| *k)
            else {
                break;
            };
            if let Some(e) = self.map.remove(&oldest) {
                self.bytes -= e.bytes;
            }
        }
    }

    /// Bytes held now.
    pub fn bytes(&self) -> usize {
        self.bytes
    }

    /// The budget in bytes.
    pub fn budget(&self) -> usize {
        self.budget
    }

    /// Number of entries.
    pub fn len(&self) -> usize {
        self.map.len()
    }

    /// Whether the cache is empty.
    pub fn is_empty(&self) -> bool {
        self.map.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::graph::{key_of, NodeKind, NodeValue};
    use std::time::Duration;

    fn result(len: usize) -> Arc<NodeResult> {
        Arc::new(NodeResult {
            value: Ok(NodeValue::Samples(Arc::new(vec![0.0; len]))),
            wall: Duration::ZERO,
            accuracy: None,
        })
    }

    fn key(i: usize) -> NodeKey {
        key_of(NodeKind::Samples, &i, &[]).unwrap()
    }

    #[test]
    fn evicts_least_recently_used_within_the_byte_budget() {
        let one = result(1000).bytes();
        let mut c = MemoryCache::new(3 * one);
        for i in 0..3 {
            c.insert(key(i), result(1000));
        }
        assert_eq!(c.len(), 3);
        // Touch 0: then 1 is the least recently used and goes first.
        assert!(c.get(&key(0)).is_some());
        c.insert(key(3), result(1000));
        assert!(c.peek(&key(1)).is_none());
        assert!(c.peek(&key(0)).is_some() && c.peek(&key(2)).is_some());
        assert!(c.bytes() <= c.budget());
        // Larger than the whole budget: not kept, nothing else evicted.
        c.insert(key(9), result(10_000));
        assert!(c.peek(&key(9)).is_none());
        assert_eq!(c.len(), 3);
        // Replacing an entry does not count it twice.
        c.insert(key(0), result(1000));
        assert_eq!(c.bytes(), 3 * one);
    }
}
