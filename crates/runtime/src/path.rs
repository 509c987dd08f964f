//! Tree paths such as `{0;1;2}`: the addresses of branches in a data tree.

use std::fmt;
use std::str::FromStr;

/// The address of one branch of a [`DataTree`](crate::DataTree): a non-empty sequence of
/// non-negative integers, printed in Grasshopper notation `{0;1;2}`.
///
/// Paths order lexicographically, element by element, and a path sorts before every longer path
/// it is a prefix of (`{0} < {0;0} < {0;1} < {1}`). Branches of a tree are kept in this order.
#[derive(Clone, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct TreePath(Vec<u32>);

impl TreePath {
    /// The path `{0}`, where single items and flat lists live.
    pub fn zero() -> Self {
        Self(vec![0])
    }

    /// A path from its indices. An empty slice gives `{0}`: a path always has an index.
    pub fn new(indices: impl Into<Vec<u32>>) -> Self {
        let indices = indices.into();
        if indices.is_empty() {
            Self::zero()
        } else {
            Self(indices)
        }
    }

    /// The indices of the path.
    pub fn indices(&self) -> &[u32] {
        &self.0
    }

    /// The number of indices (the depth of the branch).
    pub fn len(&self) -> usize {
        self.0.len()
    }

    /// Always false: a path has at least one index. Present for API symmetry with `len`.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// This path with `index` appended: `{0;1}` with 4 gives `{0;1;4}`.
    pub fn with_appended(&self, index: u32) -> Self {
        let mut v = Vec::with_capacity(self.0.len() + 1);
        v.extend_from_slice(&self.0);
        v.push(index);
        Self(v)
    }

    /// This path with its last index increased by `offset` (Grasshopper's collision offset).
    pub fn with_last_offset(&self, offset: u32) -> Self {
        let mut v = self.0.clone();
        if let Some(last) = v.last_mut() {
            *last = last.saturating_add(offset);
        }
        Self(v)
    }

    /// The last index.
    pub fn last(&self) -> u32 {
        self.0.last().copied().unwrap_or(0)
    }
}

impl fmt::Display for TreePath {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("{")?;
        for (i, index) in self.0.iter().enumerate() {
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
        Ok(Self(indices))
    }
}

impl From<&[u32]> for TreePath {
    fn from(indices: &[u32]) -> Self {
        Self::new(indices.to_vec())
    }
}

impl<const N: usize> From<[u32; N]> for TreePath {
    fn from(indices: [u32; N]) -> Self {
        Self::new(indices.to_vec())
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
