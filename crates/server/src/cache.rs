//! Definitions read and checked once, kept by pointer (content hash), each with a few idle
//! evaluators so that a request whose inputs differ from an earlier one re-runs only the nodes
//! downstream of the changed inputs.
//!
//! An evaluator is taken out of its definition's pool for the whole of one solve and put back
//! afterwards, so no two requests ever share one; a solve that fails or panics drops its
//! evaluator. The lock around the map is held only to look up, insert or evict, never while a
//! definition is parsed or a graph runs.

use std::collections::{HashMap, VecDeque};
use std::sync::{Arc, Mutex, MutexGuard, PoisonError};

use locus_runtime::Evaluator;

use crate::definition::Definition;

/// A cached definition with its idle evaluators.
#[derive(Debug)]
pub struct Entry {
    /// The definition.
    pub definition: Definition,
    idle: Mutex<Vec<Evaluator>>,
    max_idle: usize,
}

impl Entry {
    /// An evaluator for this definition: an idle one (holding the results of an earlier solve)
    /// or a new one, running everything on the calling thread.
    pub fn checkout(&self) -> (Evaluator, bool) {
        if let Some(e) = lock(&self.idle).pop() {
            return (e, true);
        }
        let mut evaluator = Evaluator::new(self.definition.plan.clone());
        // One thread per solve: the server runs solves side by side instead.
        let _ = evaluator.set_threads(1);
        (evaluator, false)
    }

    /// Returns an evaluator after a successful solve.
    pub fn checkin(&self, evaluator: Evaluator) {
        let mut idle = lock(&self.idle);
        if idle.len() < self.max_idle {
            idle.push(evaluator);
        }
    }
}

fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    // A panic while the lock is held leaves only plain data behind: go on with it.
    m.lock().unwrap_or_else(PoisonError::into_inner)
}

/// The definitions cache.
#[derive(Debug)]
pub struct Cache {
    inner: Mutex<Inner>,
    capacity: usize,
    max_idle: usize,
}

#[derive(Debug, Default)]
struct Inner {
    entries: HashMap<String, Arc<Entry>>,
    /// Pointers from least to most recently used.
    order: VecDeque<String>,
}

impl Cache {
    /// A cache of at most `capacity` definitions, each with at most `max_idle` idle evaluators.
    pub fn new(capacity: usize, max_idle: usize) -> Self {
        Self {
            inner: Mutex::new(Inner::default()),
            capacity: capacity.max(1),
            max_idle,
        }
    }

    /// The entry of a pointer, marking it recently used.
    pub fn get(&self, pointer: &str) -> Option<Arc<Entry>> {
        let mut inner = lock(&self.inner);
        let entry = inner.entries.get(pointer).cloned()?;
        touch(&mut inner.order, pointer);
        Some(entry)
    }

    /// Adds a definition (or returns the entry already there for its pointer), evicting the
    /// least recently used definition when full.
    pub fn insert(&self, definition: Definition) -> Arc<Entry> {
        let mut inner = lock(&self.inner);
        if let Some(e) = inner.entries.get(&definition.pointer).cloned() {
            touch(&mut inner.order, &definition.pointer);
            return e;
        }
        while inner.entries.len() >= self.capacity {
            let Some(old) = inner.order.pop_front() else {
                break;
            };
            inner.entries.remove(&old);
        }
        let pointer = definition.pointer.clone();
        let entry = Arc::new(Entry {
            definition,
            idle: Mutex::new(Vec::new()),
            max_idle: self.max_idle,
        });
        inner.entries.insert(pointer.clone(), entry.clone());
        inner.order.push_back(pointer);
        entry
    }

    /// The number of definitions held.
    pub fn len(&self) -> usize {
        lock(&self.inner).entries.len()
    }

    /// Whether the cache is empty.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

fn touch(order: &mut VecDeque<String>, pointer: &str) {
    if let Some(i) = order.iter().position(|p| p == pointer)
        && let Some(p) = order.remove(i)
    {
        order.push_back(p);
    }
}
