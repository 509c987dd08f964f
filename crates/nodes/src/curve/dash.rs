//! Curve › Division: Dash Pattern, a curve cut into dashes and gaps of given lengths.
//!
//! The pattern is read as a dash length, a gap length, a dash length, …, repeated from the
//! curve's start (its seam, for a closed curve) to its end, where the last piece is cut short.
//! A pattern of an odd number of lengths is repeated once to make it even, as SVG and
//! PostScript dash arrays are: `[2, 1, 1]` is `[2, 1, 1, 2, 1, 1]`, so its second 2 is a gap.
//! Grasshopper's documentation does not say what it does with an odd pattern; this rule is
//! locus's choice and is tested.

use locus_kernel::{Curve, Interval, MAX_DIVISIONS};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared};

use super::{curve_input, number_list};

/// Id of [`dash_pattern`].
pub const DASH_PATTERN: &str = "curve.dash_pattern";

/// Pieces shorter than this fraction of the curve's length are rounding left-overs at the
/// curve's end and are not output: 1e-12.
pub const DASH_LENGTH_TOLERANCE: f64 = 1e-12;

/// Registers the Dash Pattern node.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(dash_pattern());
}

/// The dash and gap pieces of a curve of length `length` for a pattern (already checked): the
/// arc-length intervals of the dashes, then of the gaps.
///
/// # Errors
/// When the curve would be cut into more than [`MAX_DIVISIONS`] pieces.
pub fn dash_intervals(
    length: f64,
    pattern: &[f64],
) -> Result<(Vec<Interval>, Vec<Interval>), NodeError> {
    let period: f64 = pattern.iter().sum();
    // Pieces of zero length are skipped, so only the non-zero entries count.
    let pieces_per_period = pattern.iter().filter(|&&p| p > 0.0).count() as f64;
    let estimate = (length / period).ceil() * pieces_per_period;
    if estimate.is_nan() || estimate > MAX_DIVISIONS as f64 {
        return Err(format!(
            "the pattern (period {period}) would cut the curve (length {length}) into about \
             {estimate} pieces, more than {MAX_DIVISIONS}"
        )
        .into());
    }
    let even = pattern.len().is_multiple_of(2);
    let stream_length = if even {
        pattern.len()
    } else {
        2 * pattern.len()
    };
    let ignore = DASH_LENGTH_TOLERANCE * length;
    let (mut dashes, mut gaps) = (Vec::new(), Vec::new());
    let mut start = 0.0;
    let mut k = 0;
    while length - start > ignore {
        let step = pattern[k % pattern.len()];
        // Sums of the period are exact multiples only in exact arithmetic: clamp to the end.
        let end = (start + step).min(length);
        if end - start > ignore {
            let piece = Interval::new(start, end);
            if (k % stream_length).is_multiple_of(2) {
                dashes.push(piece);
            } else {
                gaps.push(piece);
            }
        }
        start = end;
        k += 1;
    }
    Ok((dashes, gaps))
}

/// Dash Pattern \[Dash\]: a curve cut into dashes and gaps.
pub fn dash_pattern() -> NodeType {
    NodeType::new(DASH_PATTERN, "Dash Pattern", "Dash", "Curve")
        .subcategory("Division")
        .gh_guid("95866bbe-648e-4e2b-a97c-7d04679e94e0")
        .description(
            "Cuts a curve into dashes and gaps: the pattern lists arc lengths, a dash, a gap, \
             a dash, …, repeated from the start of the curve (its seam, if closed) to its \
             end, where the last piece is cut short. A pattern of an odd number of lengths is \
             repeated once to make it even (as SVG dash arrays are). A length of zero makes \
             no piece. Negative or non-finite lengths, an empty pattern and one that adds up \
             to zero are errors.",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("Curve to dash."))
        .input(
            Port::new("Pattern", "Pt", DataType::Number)
                .list()
                .doc("Dash and gap lengths, in model units along the curve."),
        )
        .output(
            Port::new("Dashes", "D", DataType::Curve)
                .list()
                .doc("The dashes, from the start of the curve."),
        )
        .output(
            Port::new("Gaps", "G", DataType::Curve)
                .list()
                .doc("The gaps, from the start of the curve."),
        )
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let pattern = number_list(s, 1)?;
            if pattern.is_empty() {
                return Err("pattern Pt is empty".into());
            }
            if let Some((i, p)) = pattern
                .iter()
                .enumerate()
                .find(|(_, p)| !(p.is_finite() && **p >= 0.0))
            {
                return Err(format!(
                    "pattern Pt: length {p} (item {i}) is not a finite length of zero or more"
                )
                .into());
            }
            if pattern.iter().sum::<f64>() <= 0.0 {
                return Err("pattern Pt adds up to zero: the dashes would never end".into());
            }
            let length = curve.length();
            if !(length.is_finite() && length > 0.0) {
                return Err(format!("the curve's length is {length}: nothing to dash").into());
            }
            let (dashes, gaps) = dash_intervals(length, &pattern)?;
            let [dashes, gaps] = pieces(&curve, &dashes, &gaps)?;
            s.set_list(0, dashes);
            s.set_list(1, gaps);
            Ok(())
        })
}

/// The parts of `curve` on the arc-length intervals `dashes` and `gaps` (as
/// [`dash_intervals`] gives them; the dashes' parts first), with the parameters of all their ends found in one pass.
fn pieces(
    curve: &Curve,
    dashes: &[Interval],
    gaps: &[Interval],
) -> Result<[Vec<Shared<Curve>>; 2], NodeError> {
    let mut ends: Vec<f64> = dashes
        .iter()
        .chain(gaps)
        .flat_map(|i| [i.t0, i.t1])
        .collect();
    ends.sort_by(f64::total_cmp);
    ends.dedup();
    let parameters = curve.parameters_at_lengths(&ends)?;
    let parameter = |s: f64| parameters[ends.partition_point(|&e| e < s)];
    let cut = |intervals: &[Interval]| -> Result<Vec<Shared<Curve>>, NodeError> {
        intervals
            .iter()
            .map(|piece| {
                let range = Interval::new(parameter(piece.t0), parameter(piece.t1));
                Ok(Shared::new(curve.trim(range)?))
            })
            .collect()
    };
    Ok([cut(dashes)?, cut(gaps)?])
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Circle, Line, Plane, Point3};
    use locus_runtime::{DataTree, NodeCall};

    use super::*;
    use crate::curve::test_support::*;

    fn run(curve: Curve, pattern: &[f64]) -> locus_runtime::NodeCallResult {
        NodeCall::new(&dash_pattern())
            .input(curve_tree(curve))
            .input(DataTree::from_list(pattern.to_vec()))
            .run()
    }

    fn line(length: f64) -> Curve {
        Line::new(Point3::ORIGIN, Point3::new(length, 0.0, 0.0)).into()
    }

    fn extents(tree: &DataTree) -> Vec<(f64, f64)> {
        curves(tree)
            .iter()
            .map(|c| (c.start_point().x, c.end_point().x))
            .collect()
    }

    #[test]
    fn a_line_is_cut_into_dashes_and_gaps_with_a_short_last_piece() {
        let r = run(line(10.0), &[2.0, 1.0]);
        assert_clean(&r);
        assert_eq!(
            extents(&r.outputs[0]),
            vec![(0.0, 2.0), (3.0, 5.0), (6.0, 8.0), (9.0, 10.0)]
        );
        assert_eq!(
            extents(&r.outputs[1]),
            vec![(2.0, 3.0), (5.0, 6.0), (8.0, 9.0)]
        );
    }

    #[test]
    fn an_odd_pattern_is_repeated_to_make_it_even() {
        // [2, 1, 1] reads as [2, 1, 1, 2, 1, 1]: dash 2, gap 1, dash 1, gap 2, dash 1, gap 1.
        let (dashes, gaps) = dash_intervals(8.0, &[2.0, 1.0, 1.0]).unwrap();
        let ends = |v: &[Interval]| v.iter().map(|i| (i.t0, i.t1)).collect::<Vec<_>>();
        assert_eq!(ends(&dashes), vec![(0.0, 2.0), (3.0, 4.0), (6.0, 7.0)]);
        assert_eq!(ends(&gaps), vec![(2.0, 3.0), (4.0, 6.0), (7.0, 8.0)]);
    }

    #[test]
    fn zero_lengths_make_no_piece() {
        // A zero gap: the dashes run on without a gap between them.
        let (dashes, gaps) = dash_intervals(3.0, &[1.0, 0.0]).unwrap();
        assert_eq!(dashes.len(), 3);
        assert!(gaps.is_empty());
    }

    #[test]
    fn a_circle_is_dashed_along_its_arc_length() {
        let circle = Circle::new(Plane::WORLD_XY, 1.0).unwrap();
        let quarter = std::f64::consts::FRAC_PI_2;
        let r = run(circle.into(), &[quarter, quarter]);
        assert_clean(&r);
        let dashes = curves(&r.outputs[0]);
        assert_eq!(dashes.len(), 2);
        assert_eq!(curves(&r.outputs[1]).len(), 2);
        for d in &dashes {
            assert!((d.length() - quarter).abs() < 1e-9, "{}", d.length());
        }
        assert!(close(
            dashes[1].start_point(),
            Point3::new(-1.0, 0.0, 0.0),
            1e-9
        ));
    }

    #[test]
    fn bad_patterns_are_errors() {
        // An empty pattern: the runtime does not call the node (no data on Pt).
        let r = run(line(1.0), &[]);
        assert!(curves(&r.outputs[0]).is_empty(), "{:?}", r.messages);
        assert_error(&run(line(1.0), &[1.0, -1.0]), "item 1");
        assert_error(&run(line(1.0), &[f64::NAN]), "item 0");
        assert_error(&run(line(1.0), &[0.0, 0.0]), "adds up to zero");
        assert_error(&run(line(1e9), &[1e-6, 1e-6]), "more than");
    }
}
