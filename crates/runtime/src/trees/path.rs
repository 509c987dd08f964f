//! Tree paths such as `{0;1;2}`: the addresses of branches in a data tree.

use std::fmt;
use std::str::FromStr;

/// The address of one branch of a [`DataTree`](crate::DataTree): a non-empty sequence of
/// non-negative integers, printed in Grasshopper notation `{0;1;2}`.
///
/// Paths order lexicographically, element by element, and a path sorts before every longer path
/// it is a prefix of (`{0} < {0;0} < {0;1} < {1}`). Branches of a tree are kept in this order.
///
/// Paths of up to [`TreePath::INLINE`] indices are stored inline, without a heap allocation
/// (grafting a million items makes a million paths); longer ones are boxed.
#[derive(Clone)]
pub struct TreePath(Repr);

/// The storage of a path: a small inline array, or a boxed slice for deep paths.
#[derive(Clone)]
enum Repr {
    Inline {
        len: u8,
        items: [u32; TreePath::INLINE],
    },
    Heap(Box<[u32]>),
}

impl Default for TreePath {
    /// A path with no index (only useful as a placeholder; [`TreePath::new`] never makes one).
    fn default() -> Self {
        Self(Repr::Inline {
            len: 0,
            items: [0; Self::INLINE],
        })
    }
}

impl TreePath {
    /// How many indices a path holds without a heap allocation.
    pub const INLINE: usize = 5;

    /// The path of these indices (an empty slice gives an empty path).
    fn from_slice(indices: &[u32]) -> Self {
        if indices.len() <= Self::INLINE {
            let mut items = [0; Self::INLINE];
            items[..indices.len()].copy_from_slice(indices);
            Self(Repr::Inline {
                len: indices.len() as u8,
                items,
            })
        } else {
            Self(Repr::Heap(indices.into()))
        }
    }

    /// The path `{0}`, where single items and flat lists live.
    pub fn zero() -> Self {
        Self::from_slice(&[0])
    }

    /// A path from its indices. An empty slice gives `{0}`: a path always has an index.
    pub fn new(indices: impl Into<Vec<u32>>) -> Self {
        let indices = indices.into();
        if indices.is_empty() {
            Self::zero()
        } else if indices.len() <= Self::INLINE {
            Self::from_slice(&indices)
        } else {
            Self(Repr::Heap(indices.into_boxed_slice()))
        }
    }

    /// The indices of the path.
    #[inline]
    pub fn indices(&self) -> &[u32] {
        match &self.0 {
            Repr::Inline { len, items } => &items[..usize::from(*len)],
            Repr::Heap(items) => items,
        }
    }

    /// The number of indices (the depth of the branch).
    pub fn len(&self) -> usize {
        self.indices().len()
    }

    /// Always false: a path has at least one index. Present for API symmetry with `len`.
    pub fn is_empty(&self) -> bool {
        self.indices().is_empty()
    }

    /// This path with `index` appended: `{0;1}` with 4 gives `{0;1;4}`.
    pub fn with_appended(&self, index: u32) -> Self {
        let old = self.indices();
        if old.len() < Self::INLINE {
            let mut items = [0; Self::INLINE];
            items[..old.len()].copy_from_slice(old);
            items[old.len()] = index;
            return Self(Repr::Inline {
                len: old.len() as u8 + 1,
                items,
            });
        }
        let mut v = Vec::with_capacity(old.len() + 1);
        v.extend_from_slice(old);
        v.push(index);
        Self(Repr::Heap(v.into_boxed_slice()))
    }

    /// This path with its last index increased by `offset` (Grasshopper's collision offset).
    pub fn with_last_offset(&self, offset: u32) -> Self {
        let mut path = self.clone();
        let last = match &mut path.0 {
            Repr::Inline { len, items } => items[..usize::from(*len)].last_mut(),
            Repr::Heap(items) => items.last_mut(),
        };
        if let Some(last) = last {
            *last = last.saturating_add(offset);
        }
        path
    }

    /// The last index.
    pub fn last(&self) -> u32 {
        self.indices().last().copied().unwrap_or(0)
    }
}

impl PartialEq for TreePath {
    #[inline]
    fn eq(&self, other: &Self) -> bool {
        self.indices() == other.indices()
    }
}

impl Eq for TreePath {}

impl PartialOrd for TreePath {
    #[inline]
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for TreePath {
    #[inline]
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.indices().cmp(other.indices())
    }
}

impl std::hash::Hash for TreePath {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.indices().hash(state);
    }
}

impl fmt::Debug for TreePath {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_tuple("TreePath").field(&self.indices()).finish()
    }
}

impl fmt::Display for TreePath {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("{")?;
        for (i, index) in self.indices().iter().enumerate() {
            if i > 0 {
                f.write_str(";")?;
            }
            write!(f, "{index}")?;
        }
        f.write_str("}")
    }
}

/// Why a path could not be parsed.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("invalid tree path `{text}`: {reason}")]
pub struct PathParseError {
    /// The text that was parsed.
    pub text: String,
    /// What is wrong with it.
    pub reason: &'static str,
}

impl FromStr for TreePath {
    type Err = PathParseError;

    /// Parses `{0;1;2}`; spaces are allowed around indices and the braces may be omitted
    /// (`0;1`). Indices must be non-negative integers.
    fn from_str(text: &str) -> Result<Self, Self::Err> {
        let err = |reason| PathParseError {
            text: text.to_owned(),
            reason,
        };
        let trimmed = text.trim();
        let inner = match (trimmed.strip_prefix('{'), trimmed.ends_with('}')) {
            (Some(rest), true) => &rest[..rest.len() - 1],
            (None, false) => trimmed,
            _ => return Err(err("unbalanced braces")),
        };
        if inner.trim().is_empty() {
            return Err(err("a path needs at least one index"));
        }
        let mut indices = Vec::new();
        for part in inner.split(';') {
            let part = part.trim();
            if part.is_empty() {
                return Err(err("empty index"));
            }
            let index: u32 = part
                .parse()
                .map_err(|_| err("indices must be non-negative integers"))?;
            indices.push(index);
        }
        Ok(Self::new(indices))
    }
}

impl From<&[u32]> for TreePath {
    fn from(indices: &[u32]) -> Self {
        if indices.is_empty() {
            Self::zero()
        } else {
            Self::from_slice(indices)
        }
    }
}

impl<const N: usize> From<[u32; N]> for TreePath {
    fn from(indices: [u32; N]) -> Self {
        Self::from(&indices[..])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn prints_and_parses_grasshopper_notation() {
        let p = TreePath::from([0, 1, 2]);
        assert_eq!(p.to_string(), "{0;1;2}");
        assert_eq!("{ 0; 1 ;2 }".parse::<TreePath>().unwrap(), p);
        assert_eq!("0;1;2".parse::<TreePath>().unwrap(), p);
    }

    #[test]
    fn rejects_bad_paths() {
        for bad in ["{}", "{-1}", "{0;;1}", "{0", "{a}", ""] {
            assert!(bad.parse::<TreePath>().is_err(), "{bad}");
        }
    }

    #[test]
    fn short_and_long_paths_behave_alike() {
        let long: Vec<u32> = (0..9).collect();
        let p = TreePath::new(long.clone());
        assert_eq!(p.indices(), &long[..]);
        assert_eq!(p.to_string(), "{0;1;2;3;4;5;6;7;8}");
        // Crossing the inline limit by appending, both ways of building compare equal.
        let mut q = TreePath::zero();
        for i in 1..9 {
            q = q.with_appended(i);
        }
        assert_eq!(q, p);
        assert_eq!(q.with_last_offset(2).last(), 10);
        assert_eq!(
            TreePath::from(&long[..5]),
            TreePath::new(long[..5].to_vec())
        );
        assert!(TreePath::from(&long[..5]) < p);
        assert!(TreePath::from([0, 2]) > p);
        let hash = |p: &TreePath| {
            use std::hash::{BuildHasher, RandomState};
            let s = RandomState::new();
            (s.hash_one(p), s.hash_one(p.indices()))
        };
        let (a, b) = hash(&p);
        assert_eq!(a, b);
        assert_eq!(format!("{:?}", TreePath::from([0, 1])), "TreePath([0, 1])");
        assert_eq!(std::mem::size_of::<TreePath>(), 24);
    }

    #[test]
    fn sorts_prefix_first() {
        let mut v: Vec<TreePath> = ["{1}", "{0;1}", "{0}", "{0;0}"]
            .iter()
            .map(|s| s.parse().unwrap())
            .collect();
        v.sort();
        let s: Vec<String> = v.iter().map(ToString::to_string).collect();
        assert_eq!(s, ["{0}", "{0;0}", "{0;1}", "{1}"]);
    }
}
