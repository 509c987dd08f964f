//! Best-candidate sampling (Mitchell's algorithm): points spread evenly but irregularly over a
//! rectangle or a box.
//!
//! Each new point is the best of [`BEST_CANDIDATES`] random candidates: the one farthest from
//! every point placed so far (given points included). The random numbers come from the caller
//! (a function returning numbers in `[0, 1)`), so that the result is reproducible for a seed;
//! candidates are drawn as x, then y, then z (z only in three dimensions). Nearest distances are
//! found in a uniform grid of cells of about the final mean spacing, searched ring by ring
//! outwards, so that sampling `n` points costs about `n · candidates` grid look-ups.

use crate::{BoundingBox, Point3};

/// How many random candidates compete for each new point: 10.
pub const BEST_CANDIDATES: usize = 10;

/// The most cells of the search grid along one axis: 4096.
const MAX_CELLS_PER_AXIS: usize = 4096;

/// The most cells of the search grid per point expected in it: 8 (so that the grid of a
/// surface spread through a box stays in proportion to the points, not to the box's volume).
const MAX_CELLS_PER_POINT: usize = 8;

/// Below this many points held, a query checks them one by one: 64.
const BRUTE_FORCE_POINTS: usize = 64;

/// A uniform grid over `[0, extent]` per axis holding points, for nearest-distance queries.
struct Grid {
    cell: f64,
    extents: [f64; 3],
    dims: [usize; 3],
    cells: Vec<Vec<Point3>>,
    /// Every point held, for small counts.
    all: Vec<Point3>,
    /// Points outside the grid, checked one by one.
    outside: Vec<Point3>,
}

impl Grid {
    /// A grid over `extents` with cubic cells of side `cell` (made larger where more than
    /// [`MAX_CELLS_PER_AXIS`] per axis or [`MAX_CELLS_PER_POINT`] per expected point would be
    /// needed).
    fn with_cell(extents: [f64; 3], mut cell: f64, expected: usize) -> Self {
        let longest = extents.iter().copied().fold(0.0, f64::max);
        if !(cell.is_finite() && cell > 0.0) {
            cell = longest.max(1.0);
        }
        cell = cell.max(longest / MAX_CELLS_PER_AXIS as f64);
        let cells =
            |cell: f64| -> f64 { extents.iter().map(|e| (e / cell).ceil().max(1.0)).product() };
        let budget = (MAX_CELLS_PER_POINT * expected.max(1)) as f64;
        while cells(cell) > budget {
            cell *= 1.25;
        }
        let dims = extents.map(|e| ((e / cell).ceil() as usize).clamp(1, MAX_CELLS_PER_AXIS));
        Self {
            cell,
            extents,
            dims,
            cells: vec![Vec::new(); dims[0] * dims[1] * dims[2]],
            all: Vec::new(),
            outside: Vec::new(),
        }
    }

    /// A grid over `extents` with cells of about the mean spacing of `expected` points.
    fn new(extents: [f64; 3], expected: usize) -> Self {
        let axes: Vec<f64> = extents.iter().copied().filter(|&e| e > 0.0).collect();
        let measure: f64 = axes.iter().product();
        let cell = (measure / expected.max(1) as f64).powf(1.0 / axes.len().max(1) as f64);
        Self::with_cell(extents, cell, expected)
    }

    /// The cell coordinate of `x` along `axis`: cells are closed, so a point on the far side of
    /// the grid belongs to its last cell.
    fn coordinate(&self, x: f64, axis: usize) -> Option<usize> {
        let c = (x / self.cell).floor();
        let inside = c >= 0.0 && ((c as usize) < self.dims[axis] || x <= self.extents[axis]);
        inside.then(|| (c as usize).min(self.dims[axis] - 1))
    }

    fn cell_of(&self, p: Point3) -> Option<[usize; 3]> {
        Some([
            self.coordinate(p.x, 0)?,
            self.coordinate(p.y, 1)?,
            self.coordinate(p.z, 2)?,
        ])
    }

    fn index(&self, c: [usize; 3]) -> usize {
        (c[0] * self.dims[1] + c[1]) * self.dims[2] + c[2]
    }

    fn insert(&mut self, p: Point3) {
        self.all.push(p);
        match self.cell_of(p) {
            Some(c) => {
                let i = self.index(c);
                self.cells[i].push(p);
            }
            None => self.outside.push(p),
        }
    }

    /// The squared distance from `p` to the nearest point held, or infinity.
    fn nearest_squared(&self, p: Point3) -> f64 {
        let brute = |points: &[Point3]| {
            points
                .iter()
                .map(|q| (*q - p).length_squared())
                .fold(f64::INFINITY, f64::min)
        };
        if self.all.len() <= BRUTE_FORCE_POINTS {
            return brute(&self.all);
        }
        let Some(c) = self.cell_of(p) else {
            return brute(&self.all);
        };
        let mut best = brute(&self.outside);
        let mut seen = self.outside.len();
        let reach = self.dims.iter().copied().max().unwrap_or(1);
        for ring in 0..=reach {
            // Every point not yet visited is at least (ring − 1) cells away from p.
            let bound = (ring as f64 - 1.0).max(0.0) * self.cell;
            if best <= bound * bound || seen == self.all.len() {
                break;
            }
            let r = ring as isize;
            let range = |axis: usize| {
                let lo = (c[axis] as isize - r).max(0) as usize;
                let hi = (c[axis] as isize + r).min(self.dims[axis] as isize - 1) as usize;
                lo..=hi
            };
            for i in range(0) {
                for j in range(1) {
                    let edge = i.abs_diff(c[0]) == ring || j.abs_diff(c[1]) == ring;
                    let mut visit = |k: usize| {
                        for q in &self.cells[self.index([i, j, k])] {
                            best = best.min((*q - p).length_squared());
                            seen += 1;
                        }
                    };
                    if edge {
                        range(2).for_each(&mut visit);
                    } else {
                        // Only the two faces of the shell across z.
                        if let Some(k) = c[2].checked_sub(ring) {
                            visit(k);
                        }
                        if ring > 0 && c[2] + ring < self.dims[2] {
                            visit(c[2] + ring);
                        }
                    }
                }
            }
        }
        best
    }
}

/// `count` points in `[0, x) × [0, y) × [0, z)` (`extents`; give a zero extent for a flat
/// axis, whose coordinate is then 0), each the best of [`BEST_CANDIDATES`] candidates against
/// the points before it and `existing` (coordinates in the same frame; they may lie outside).
/// `random` returns numbers in `[0, 1)`. Extents that are not finite or are negative give no
/// points.
pub fn best_candidate_samples(
    extents: [f64; 3],
    count: usize,
    existing: &[Point3],
    mut random: impl FnMut() -> f64,
) -> Vec<Point3> {
    if extents.iter().any(|e| !(e.is_finite() && *e >= 0.0)) {
        return Vec::new();
    }
    let mut grid = Grid::new(extents, count + existing.len());
    for p in existing.iter().filter(|p| p.is_finite()) {
        grid.insert(*p);
    }
    let mut out = Vec::with_capacity(count);
    let mut draw = |e: f64| if e > 0.0 { random() * e } else { 0.0 };
    for _ in 0..count {
        let mut best = (f64::NEG_INFINITY, Point3::ORIGIN);
        for _ in 0..BEST_CANDIDATES {
            let x = draw(extents[0]);
            let y = draw(extents[1]);
            let z = draw(extents[2]);
            let candidate = Point3::new(x, y, z);
            let d = grid.nearest_squared(candidate);
            if d > best.0 {
                best = (d, candidate);
            }
        }
        grid.insert(best.1);
        out.push(best.1);
    }
    out
}

/// `count` points drawn by `candidate`, each the best of [`BEST_CANDIDATES`] candidates
/// against the points before it and `existing`: the generalisation of
/// [`best_candidate_samples`] to any region (a curve, a surface, a mesh) that can draw random
/// points of itself. `bounds` should hold the region (points outside it are found too, only
/// more slowly); `spacing` is the expected distance between neighbouring points, the size of
/// the search grid's cells. A candidate function that gives `None` (a draw that failed) stops
/// the sampling early, so fewer points come back.
pub fn best_candidate_points(
    bounds: BoundingBox,
    spacing: f64,
    count: usize,
    existing: &[Point3],
    mut candidate: impl FnMut() -> Option<Point3>,
) -> Vec<Point3> {
    if !(bounds.is_finite() && bounds.is_valid()) {
        return Vec::new();
    }
    let origin = bounds.min;
    let d = bounds.diagonal();
    let mut grid = Grid::with_cell([d.x, d.y, d.z], spacing, count + existing.len());
    let local = |p: Point3| Point3::from_vector(p - origin);
    for p in existing.iter().filter(|p| p.is_finite()) {
        grid.insert(local(*p));
    }
    let mut out = Vec::with_capacity(count);
    'points: for _ in 0..count {
        let mut best = (f64::NEG_INFINITY, Point3::ORIGIN);
        for _ in 0..BEST_CANDIDATES {
            let Some(c) = candidate().filter(|c| c.is_finite()) else {
                break 'points;
            };
            let d = grid.nearest_squared(local(c));
            if d > best.0 {
                best = (d, c);
            }
        }
        grid.insert(local(best.1));
        out.push(best.1);
    }
    out
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// A small linear congruential generator, for the tests of this module and of
    /// `mesh::populate`.
    pub(crate) fn lcg(seed: u64) -> impl FnMut() -> f64 {
        let mut state = seed;
        move || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1_u64 << 53) as f64
        }
    }

    fn brute_nearest(points: &[Point3], p: Point3) -> f64 {
        points
            .iter()
            .map(|q| (*q - p).length_squared())
            .fold(f64::INFINITY, f64::min)
    }

    #[test]
    fn the_grid_finds_the_nearest_point_exactly() {
        let mut random = lcg(7);
        let mut grid = Grid::new([3.0, 1.0, 0.0], 300);
        let mut held = Vec::new();
        for _ in 0..300 {
            let p = Point3::new(random() * 3.0, random(), 0.0);
            grid.insert(p);
            held.push(p);
        }
        let far = Point3::new(-5.0, 0.5, 0.0);
        grid.insert(far);
        held.push(far);
        for _ in 0..200 {
            let q = Point3::new(random() * 3.0, random(), 0.0);
            assert_eq!(grid.nearest_squared(q), brute_nearest(&held, q));
        }
    }

    #[test]
    fn the_grid_finds_the_nearest_point_in_three_dimensions() {
        let mut random = lcg(11);
        let mut grid = Grid::new([1.0, 2.0, 0.5], 500);
        let mut held = Vec::new();
        for _ in 0..500 {
            let p = Point3::new(random(), random() * 2.0, random() * 0.5);
            grid.insert(p);
            held.push(p);
        }
        for _ in 0..300 {
            let q = Point3::new(random(), random() * 2.0, random() * 0.5);
            assert_eq!(grid.nearest_squared(q), brute_nearest(&held, q));
        }
        assert_eq!(
            grid.nearest_squared(Point3::new(1.0, 2.0, 0.5)),
            brute_nearest(&held, Point3::new(1.0, 2.0, 0.5))
        );
    }

    #[test]
    fn samples_stay_inside_and_spread_out() {
        let pts = best_candidate_samples([2.0, 1.0, 0.0], 200, &[], lcg(1));
        assert_eq!(pts.len(), 200);
        assert!(
            pts.iter()
                .all(|p| (0.0..2.0).contains(&p.x) && (0.0..1.0).contains(&p.y) && p.z == 0.0)
        );
        // Uniform random points of this density come as close as about 1e-3; best-candidate
        // points keep a good part of the mean spacing (0.1) between them.
        let min = (0..pts.len())
            .flat_map(|i| (0..i).map(move |j| (i, j)))
            .map(|(i, j)| pts[i].distance(pts[j]))
            .fold(f64::INFINITY, f64::min);
        assert!(min > 0.02, "closest pair {min}");
    }

    #[test]
    fn the_same_random_numbers_give_the_same_points_and_existing_points_are_avoided() {
        let a = best_candidate_samples([1.0, 1.0, 1.0], 30, &[], lcg(3));
        let b = best_candidate_samples([1.0, 1.0, 1.0], 30, &[], lcg(3));
        assert_eq!(a, b);
        let existing = [Point3::new(0.5, 0.5, 0.0)];
        let c = best_candidate_samples([1.0, 1.0, 0.0], 5, &existing, lcg(3));
        assert!(c.iter().all(|p| p.distance(existing[0]) > 0.1));
        assert!(best_candidate_samples([f64::NAN, 1.0, 0.0], 5, &[], lcg(3)).is_empty());
        assert_eq!(
            best_candidate_samples([0.0, 0.0, 0.0], 2, &[], lcg(3)).len(),
            2
        );
    }
}
