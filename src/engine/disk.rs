//! Reference images on disk: a [`NodeResult`] of the reference node to and from the bytes of
//! [`DiskCache`] ([`ImagePayload`]), keyed by the node key.
//!
//! Only complete, successful results are stored. A file that does not decode (corrupt,
//! foreign, another version) is ignored and the node is computed again. The payload holds the
//! reference's f64 pixels as computed (row 0 at the bottom; the display image is made from
//! them as the node makes it) and the RON text of its [`ReferenceMethod`].

use super::disk_cache::{DiskCache, ImagePayload};
use crate::core::recon::ReferenceMethod;
use crate::model::{Accuracy, ReferenceData};
use crate::scene::graph::{NodeKey, NodeResult, NodeValue};
use std::sync::Arc;
use std::time::Duration;

/// The cached result of `key`, if a valid one is on disk.
pub(crate) fn load(disk: &DiskCache, key: &NodeKey) -> Option<NodeResult> {
    let bytes = disk.get(key.kind.name(), &key.hash)?;
    // `from_bytes` checks that the values are exactly width × height.
    let p = ImagePayload::from_bytes(&bytes)?;
    // Reference images are square.
    if p.width != p.height {
        return None;
    }
    let method: ReferenceMethod = ron::from_str(&p.method).ok()?;
    Some(NodeResult {
        value: Ok(NodeValue::Reference(Arc::new(ReferenceData::new(
            p.width as usize,
            p.values,
            p.error_estimate,
            method,
        )))),
        // The same accuracy as when computed (it is a function of the method and the error
        // estimate): a render from the cache writes the same bytes as one that computed it.
        wall: Duration::ZERO,
        accuracy: Accuracy::reference(method, p.error_estimate),
    })
}

/// Stores a successful reference result under `key`; failures to write are reported on
/// stderr once per result and otherwise ignored (the cache is an optimisation).
pub(crate) fn store(disk: &DiskCache, key: &NodeKey, result: &NodeResult) {
    let Ok(NodeValue::Reference(r)) = &result.value else {
        return;
    };
    let Ok(method) = ron::to_string(&r.method) else {
        return;
    };
    let payload = ImagePayload {
        width: r.image.width as u32,
        height: r.image.height as u32,
        values: r.pixels.as_ref().clone(),
        error_estimate: r.error_estimate,
        method,
    };
    if let Err(e) = disk.put(key.kind.name(), &key.hash, &payload.to_bytes()) {
        eprintln!("samplescope: disk cache: {e}");
    }
}
