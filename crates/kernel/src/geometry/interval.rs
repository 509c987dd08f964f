//! Intervals: the domains of curves and surfaces, and ranges of numbers.

use crate::{Error, Result};

/// A closed interval of real numbers from `t0` to `t1`, which may be increasing or decreasing
/// (Grasshopper's *domain*).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Interval {
    /// The start of the interval.
    pub t0: f64,
    /// The end of the interval.
    pub t1: f64,
}

impl Interval {
    /// The unit interval 0 to 1.
    pub const UNIT: Self = Self::new(0.0, 1.0);

    /// Creates an interval from its two ends, in the given order.
    #[inline]
    pub const fn new(t0: f64, t1: f64) -> Self {
        Self { t0, t1 }
    }

    /// The signed length `t1 − t0` (negative for a decreasing interval).
    #[inline]
    pub fn length(self) -> f64 {
        self.t1 - self.t0
    }

    /// The smaller end.
    #[inline]
    pub fn min(self) -> f64 {
        self.t0.min(self.t1)
    }

    /// The larger end.
    #[inline]
    pub fn max(self) -> f64 {
        self.t0.max(self.t1)
    }

    /// The value in the middle.
    #[inline]
    pub fn mid(self) -> f64 {
        0.5 * (self.t0 + self.t1)
    }

    /// Whether `t1 > t0`.
    #[inline]
    pub fn is_increasing(self) -> bool {
        self.t1 > self.t0
    }

    /// Whether `t1 < t0`.
    #[inline]
    pub fn is_decreasing(self) -> bool {
        self.t1 < self.t0
    }

    /// Whether both ends are finite.
    #[inline]
    pub fn is_finite(self) -> bool {
        self.t0.is_finite() && self.t1.is_finite()
    }

    /// The actual parameter at the normalized parameter `s`: `t0 + s (t1 − t0)`.
    #[inline]
    pub fn parameter_at(self, s: f64) -> f64 {
        // Written so that s = 0 and s = 1 give the ends exactly.
        (1.0 - s) * self.t0 + s * self.t1
    }

    /// The normalized parameter of `t`: 0 at `t0`, 1 at `t1` (both exactly).
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when the interval has zero length or is not finite,
    /// [`Error::NotFinite`] when `t` is NaN or infinite.
    pub fn normalized_parameter_at(self, t: f64) -> Result<f64> {
        let len = self.length();
        if len == 0.0 || !len.is_finite() {
            return Err(Error::InvalidInput(format!(
                "interval {} to {} has zero length",
                self.t0, self.t1
            )));
        }
        if !t.is_finite() {
            return Err(Error::NotFinite { what: "parameter" });
        }
        // As openNURBS: the end maps to exactly 1 even where (t1 − t0) / (t1 − t0) would not.
        if t == self.t1 {
            return Ok(1.0);
        }
        Ok((t - self.t0) / len)
    }

    /// Maps `t` from this interval to `target`, keeping its normalized parameter (Grasshopper's
    /// *Remap Numbers*).
    ///
    /// # Errors
    /// As [`normalized_parameter_at`](Self::normalized_parameter_at).
    pub fn remap(self, t: f64, target: Self) -> Result<f64> {
        Ok(target.parameter_at(self.normalized_parameter_at(t)?))
    }

    /// The same interval made increasing: `min()` to `max()`.
    #[inline]
    pub fn increasing(self) -> Self {
        Self::new(self.min(), self.max())
    }

    /// Whether both ends are equal (the interval is a single number).
    #[inline]
    pub fn is_singleton(self) -> bool {
        self.t0 == self.t1
    }

    /// `t` clamped to the interval, whatever its direction (NaN stays NaN).
    #[inline]
    pub fn clamp(self, t: f64) -> f64 {
        if t.is_nan() {
            return t;
        }
        t.max(self.min()).min(self.max())
    }

    /// The smallest increasing interval containing both intervals.
    #[inline]
    pub fn union(self, other: Self) -> Self {
        Self::new(self.min().min(other.min()), self.max().max(other.max()))
    }

    /// The increasing interval common to both, or `None` when they do not overlap (touching
    /// ends give a singleton).
    #[inline]
    pub fn intersection(self, other: Self) -> Option<Self> {
        let lo = self.min().max(other.min());
        let hi = self.max().min(other.max());
        (lo <= hi).then_some(Self::new(lo, hi))
    }

    /// Whether `t` lies in the interval (ends included), whatever its direction.
    #[inline]
    pub fn contains(self, t: f64) -> bool {
        t >= self.min() && t <= self.max()
    }

    /// The `count` equal parts, in order: part `k` runs from the parameter at `k / count` to
    /// the one at `(k + 1) / count`, so neighbours share their bounds exactly and the last part
    /// ends exactly on `t1` (a decreasing interval gives decreasing parts). No parts for 0.
    pub fn divide(self, count: usize) -> Vec<Self> {
        let at = |k: usize| {
            if k == count {
                self.t1
            } else {
                self.parameter_at(k as f64 / count as f64)
            }
        };
        (0..count).map(|k| Self::new(at(k), at(k + 1))).collect()
    }

    /// The same interval with its ends swapped.
    #[inline]
    pub fn reversed(self) -> Self {
        Self::new(self.t1, self.t0)
    }
}

/// A pair of intervals, one per surface direction (Grasshopper's *Domain²*, Rhino's
/// `UVInterval`): a rectangle of surface parameters, each side possibly decreasing.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct UvInterval {
    /// The interval in the u direction.
    pub u: Interval,
    /// The interval in the v direction.
    pub v: Interval,
}

impl UvInterval {
    /// The unit square `[0, 1] × [0, 1]`.
    pub const UNIT: Self = Self::new(Interval::UNIT, Interval::UNIT);

    /// Creates the pair from its two intervals.
    #[inline]
    pub const fn new(u: Interval, v: Interval) -> Self {
        Self { u, v }
    }

    /// Whether all four ends are finite.
    #[inline]
    pub fn is_finite(self) -> bool {
        self.u.is_finite() && self.v.is_finite()
    }

    /// The `u_count × v_count` equal parts, u-major (every v part of the first u part, then
    /// the next u part), made of the parts of [`Interval::divide`].
    pub fn divide(self, u_count: usize, v_count: usize) -> Vec<Self> {
        let (us, vs) = (self.u.divide(u_count), self.v.divide(v_count));
        let mut parts = Vec::with_capacity(us.len().saturating_mul(vs.len()));
        for &u in &us {
            parts.extend(vs.iter().map(|&v| Self::new(u, v)));
        }
        parts
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalized_round_trip_on_decreasing_domain() {
        let d = Interval::new(10.0, 2.0);
        assert_eq!(d.parameter_at(0.0), 10.0);
        assert_eq!(d.parameter_at(1.0), 2.0);
        assert_eq!(d.normalized_parameter_at(4.0).unwrap(), 0.75);
    }

    #[test]
    fn normalized_end_is_exactly_one() {
        let d = Interval::new(0.1, 0.7);
        assert_eq!(d.normalized_parameter_at(0.7).unwrap(), 1.0);
        assert_eq!(d.normalized_parameter_at(0.1).unwrap(), 0.0);
        assert!(d.normalized_parameter_at(f64::NAN).is_err());
    }

    #[test]
    fn remap_between_domains() {
        let from = Interval::new(0.0, 10.0);
        let to = Interval::new(1.0, -1.0);
        assert_eq!(from.remap(2.5, to).unwrap(), 0.5);
        assert_eq!(from.remap(10.0, to).unwrap(), -1.0);
    }

    #[test]
    fn union_intersection_clamp() {
        let a = Interval::new(3.0, 1.0);
        let b = Interval::new(2.0, 5.0);
        assert_eq!(a.increasing(), Interval::new(1.0, 3.0));
        assert_eq!(a.union(b), Interval::new(1.0, 5.0));
        assert_eq!(a.intersection(b), Some(Interval::new(2.0, 3.0)));
        assert_eq!(a.intersection(Interval::new(4.0, 6.0)), None);
        assert_eq!(
            a.intersection(Interval::new(3.0, 6.0)),
            Some(Interval::new(3.0, 3.0))
        );
        assert_eq!(a.clamp(7.0), 3.0);
        assert_eq!(a.clamp(-7.0), 1.0);
        assert!(a.clamp(f64::NAN).is_nan());
        assert!(Interval::new(2.0, 2.0).is_singleton());
    }

    #[test]
    fn zero_length_has_no_normalized_parameter() {
        assert!(
            Interval::new(3.0, 3.0)
                .normalized_parameter_at(3.0)
                .is_err()
        );
    }

    #[test]
    fn uv_interval_divides_u_major_and_ends_exactly() {
        let d = UvInterval::new(Interval::new(0.0, 0.3), Interval::new(2.0, -1.0));
        let parts = d.divide(3, 2);
        assert_eq!(parts.len(), 6);
        assert_eq!(parts[0].u, parts[1].u);
        assert_eq!(parts[1].v, Interval::new(0.5, -1.0));
        assert_eq!(parts[5].u.t1, 0.3);
        assert_eq!(parts[5].v.t1, -1.0);
        for w in parts.windows(2) {
            if w[0].u == w[1].u {
                assert_eq!(w[0].v.t1, w[1].v.t0);
            }
        }
        assert!(d.divide(0, 4).is_empty());
    }
}
