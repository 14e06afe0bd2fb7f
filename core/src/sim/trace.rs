//! A bounded recorder of chosen variables, one sample per scan.

use std::collections::VecDeque;

use crate::program::Slot;
use crate::vm::Value;

/// The values of the traced variables after one scan.
#[derive(Debug, Clone, PartialEq)]
pub struct TraceSample {
    /// The scan number (1-based).
    pub scan: u64,
    /// The virtual time at the end of the scan, in nanoseconds.
    pub time_ns: i64,
    /// One value per traced variable, in the order they were chosen.
    pub values: Vec<Value>,
}

/// A ring buffer of samples: when full, the oldest sample is dropped.
#[derive(Debug, Clone, PartialEq)]
pub struct Trace {
    slots: Vec<(String, Slot)>,
    capacity: usize,
    samples: VecDeque<TraceSample>,
}

impl Trace {
    /// A trace of `slots` keeping at most `capacity` samples.
    pub fn new(slots: Vec<(String, Slot)>, capacity: usize) -> Self {
        Trace { slots, capacity, samples: VecDeque::new() }
    }

    /// True when variables are chosen and the capacity is not zero.
    pub fn is_enabled(&self) -> bool {
        !self.slots.is_empty() && self.capacity > 0
    }

    /// The most samples kept (the oldest are dropped).
    pub fn capacity(&self) -> usize {
        self.capacity
    }

    /// The traced variables' paths, in order.
    pub fn paths(&self) -> impl Iterator<Item = &str> {
        self.slots.iter().map(|(p, _)| p.as_str())
    }

    pub(crate) fn slots(&self) -> &[(String, Slot)] {
        &self.slots
    }

    /// The samples, oldest first.
    pub fn samples(&self) -> impl Iterator<Item = &TraceSample> {
        self.samples.iter()
    }

    /// How many samples are kept now.
    pub fn len(&self) -> usize {
        self.samples.len()
    }

    /// True when nothing is recorded.
    pub fn is_empty(&self) -> bool {
        self.samples.is_empty()
    }

    pub(crate) fn push(&mut self, sample: TraceSample) {
        if self.samples.len() == self.capacity {
            self.samples.pop_front();
        }
        self.samples.push_back(sample);
    }

    /// Drops the samples of scans after `scan` (a rewind).
    pub(crate) fn truncate_after(&mut self, scan: u64) {
        while self.samples.back().is_some_and(|s| s.scan > scan) {
            self.samples.pop_back();
        }
    }

    pub(crate) fn clear(&mut self) {
        self.samples.clear();
    }
}
