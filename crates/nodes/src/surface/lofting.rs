//! Surface › Freeform: Ruled Surface, Loft and Loft Options, surfaces through curves.
//!
//! Both make their curves compatible first (the kernel's `NurbsCurve::make_compatible`: each
//! reparameterized to `0..1`, raised to the highest degree among them, with all their knots
//! merged), so `u` runs along the curves on `0..1`. Curve directions and closed curves' seams
//! are taken as given unless the loft's options say `adjust` (the kernel's
//! `align_loft_sections`, Rhino's seam adjustment).
//!
//! Grasshopper's Loft takes a Loft Options object from its Loft Options component. In locus
//! the options are a text of words, which the Loft Options node writes: the type (`normal`,
//! `loose`, `tight`, `straight`, `uniform`), `closed` to join the last section back to the
//! first, and `adjust` to align closed sections' directions and seams.

use locus_kernel::{Brep, Interval, Line, LoftType, NurbsCurve, NurbsSurface, align_loft_sections};
use locus_runtime::{DataType, NodeError, NodeType, Port, Shared};

use super::brep::surface_node;

/// Id of [`ruled_surface`].
pub const RULED_SURFACE: &str = "surface.ruled_surface";
/// Id of [`loft`].
pub const LOFT: &str = "surface.loft";
/// Id of [`loft_options_node`].
pub const LOFT_OPTIONS: &str = "surface.loft_options";
/// Id of [`revolution`].
pub const REVOLUTION: &str = "surface.revolution";

/// Registers Ruled Surface, Loft, Loft Options and Revolution.
pub fn register(registry: &mut locus_runtime::NodeRegistry) {
    registry.register(ruled_surface());
    registry.register(loft());
    registry.register(loft_options_node());
    registry.register(revolution());
}

fn valid_nurbs(curve: &locus_kernel::Curve, name: &str) -> Result<NurbsCurve, NodeError> {
    if !curve.is_valid() {
        return Err(NodeError(format!(
            "input {name}: the curve is not valid (not finite or degenerate)"
        )));
    }
    Ok(curve.to_nurbs())
}

/// Ruled Surface \[RuleSrf\]: the surface of straight lines between two curves.
pub fn ruled_surface() -> NodeType {
    surface_node(RULED_SURFACE, "Ruled Surface", "RuleSrf", "Freeform")
        .gh_guid("6e5de495-ba76-42d0-9985-a5c265e9aeca")
        .description(
            "Creates the surface of straight lines between two curves, joining points of equal \
             normalized parameter. The curves are made compatible (both on 0 to 1, the higher \
             degree, merged knots); the surface has degree 1 across, domain 0 to 1 both ways, \
             Curve A at v = 0 and Curve B at v = 1. Curve directions are used as given.",
        )
        .input(Port::new("Curve A", "A", DataType::Curve).doc("The first curve (v = 0)."))
        .input(Port::new("Curve B", "B", DataType::Curve).doc("The second curve (v = 1)."))
        .output(Port::new("Surface", "S", DataType::Surface).doc("The ruled surface."))
        .lift2(
            |a: &Shared<locus_kernel::Curve>, b: &Shared<locus_kernel::Curve>| {
                let (a, b) = (valid_nurbs(a, "A")?, valid_nurbs(b, "B")?);
                Ok(Shared::new(NurbsSurface::ruled(&a, &b)?))
            },
        )
}

/// What a loft's Options text says.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct LoftOptions {
    kind: LoftType,
    closed: bool,
    adjust: bool,
}

/// The loft type, closure and seam adjustment from the Options text.
fn loft_options(text: &str) -> Result<LoftOptions, NodeError> {
    let mut options = LoftOptions {
        kind: LoftType::Normal,
        closed: false,
        adjust: false,
    };
    for word in text
        .split(|c: char| c.is_whitespace() || c == ',' || c == ';')
        .filter(|w| !w.is_empty())
    {
        match word.to_ascii_lowercase().as_str() {
            "normal" => options.kind = LoftType::Normal,
            "loose" => options.kind = LoftType::Loose,
            "tight" => options.kind = LoftType::Tight,
            "straight" => options.kind = LoftType::Straight,
            "uniform" => options.kind = LoftType::Uniform,
            "closed" => options.closed = true,
            "open" => options.closed = false,
            "adjust" => options.adjust = true,
            other => {
                return Err(NodeError(format!(
                    "input O: unknown loft option `{other}`; use normal, loose, tight, \
                     straight or uniform, open or closed, and adjust (developable lofts are \
                     not supported)"
                )));
            }
        }
    }
    Ok(options)
}

/// The Options text of a loft.
fn options_text(options: LoftOptions) -> String {
    let kind = match options.kind {
        LoftType::Normal => "normal",
        LoftType::Loose => "loose",
        LoftType::Tight => "tight",
        LoftType::Straight => "straight",
        LoftType::Uniform => "uniform",
    };
    let mut text = kind.to_owned();
    if options.closed {
        text.push_str(" closed");
    }
    if options.adjust {
        text.push_str(" adjust");
    }
    text
}

/// Loft Options \[Loft Opt\]: the options of a loft, as the text Loft takes.
pub fn loft_options_node() -> NodeType {
    surface_node(LOFT_OPTIONS, "Loft Options", "Loft Opt", "Freeform")
        .gh_guid("45f19d16-1c9f-4b0f-a9a6-45a77f3d206c")
        .description(
            "Makes the options of a loft, as the text of words Loft's O input takes: the type \
             (Rhino's numbers: 0 normal, 1 loose, 2 tight, 3 straight, 5 uniform; 4, \
             developable, is not supported), `closed` and `adjust`. Rebuilding or refitting \
             the sections (Rbd, Rft above 0) is not supported and is an error.",
        )
        .input(
            Port::new("Closed", "Cls", DataType::Boolean)
                .default_value(false)
                .doc("Join the last section back to the first. Default false."),
        )
        .input(
            Port::new("Adjust", "Adj", DataType::Boolean)
                .default_value(true)
                .doc(
                    "Adjust the seams: closed sections turned to run the way of the first, \
                     each seam moved to the point nearest the previous seam. Default true.",
                ),
        )
        .input(
            Port::new("Rebuild", "Rbd", DataType::Integer)
                .default_value(0_i64)
                .doc(
                    "Rebuild the sections with this many control points; only 0 (no) is supported.",
                ),
        )
        .input(
            Port::new("Refit", "Rft", DataType::Number)
                .default_value(0.0)
                .doc("Refit the sections within this tolerance; only 0 (no) is supported."),
        )
        .input(
            Port::new("Type", "T", DataType::Integer)
                .default_value(0_i64)
                .doc("0 normal, 1 loose, 2 tight, 3 straight, 5 uniform. Default 0."),
        )
        .output(
            Port::new("Options", "O", DataType::Text)
                .doc("The loft options, as words (for example `tight closed adjust`)."),
        )
        .solve(|s| {
            let closed = *s.item::<bool>(0)?;
            let adjust = *s.item::<bool>(1)?;
            let rebuild = *s.item::<i64>(2)?;
            let refit = *s.item::<f64>(3)?;
            if rebuild != 0 {
                return Err(NodeError(format!(
                    "input Rbd: rebuilding the sections ({rebuild} points) is not supported; use 0"
                )));
            }
            if refit != 0.0 {
                return Err(NodeError(format!(
                    "input Rft: refitting the sections (tolerance {refit}) is not supported; use 0"
                )));
            }
            let kind = match *s.item::<i64>(4)? {
                0 => LoftType::Normal,
                1 => LoftType::Loose,
                2 => LoftType::Tight,
                3 => LoftType::Straight,
                5 => LoftType::Uniform,
                4 => return Err("input T: developable lofts (type 4) are not supported".into()),
                other => {
                    return Err(NodeError(format!(
                        "input T: {other} is not a loft type (0 normal, 1 loose, 2 tight, 3 \
                         straight, 5 uniform)"
                    )));
                }
            };
            s.set(
                0,
                options_text(LoftOptions {
                    kind,
                    closed,
                    adjust,
                }),
            );
            Ok(())
        })
}

/// Loft \[Loft\]: a surface through section curves.
pub fn loft() -> NodeType {
    surface_node(LOFT, "Loft", "Loft", "Freeform")
        .gh_guid("a7a41d0a-2188-4f7a-82cc-1a2c4e4ec850")
        .description(
            "Creates a surface through a list of section curves, as a one-face B-rep. The \
             sections are made compatible (each on 0 to 1, the highest degree, merged knots) \
             and their control points are interpolated across them: cubic (degree sections − \
             1 below four sections), degree 1 for a straight loft. Sections get parameters on \
             0 to 1 across: averaged chord lengths (normal, straight), their square roots \
             (tight: closer to the sections where they turn sharply) or equal steps (uniform); \
             the surface passes through every section. A loose loft takes the sections' \
             control points as its own: it passes through the first and last sections and \
             near the others. u runs along the sections, v across. A closed loft joins the \
             last section back to the first (only continuous, not smooth, at that seam unless \
             straight). Curve directions and seams are used as given unless the options say \
             `adjust`.",
        )
        .input(
            Port::new("Curves", "C", DataType::Curve)
                .list()
                .doc("The section curves, in order; nulls are left out with a warning."),
        )
        .input(
            Port::new("Options", "O", DataType::Text)
                .default_value("normal".to_string())
                .doc(
                    "Loft options as words, as Loft Options writes them: the type (`normal`, \
                     `loose`, `tight`, `straight` or `uniform`), `closed` to close the loft and \
                     `adjust` to align closed sections' directions and seams. Default `normal` \
                     (open, sections as given).",
                ),
        )
        .output(Port::new("Loft", "L", DataType::Brep).doc("The loft, a one-face B-rep."))
        .solve(|s| {
            let options = loft_options(s.item::<String>(1)?)?;
            let list = s.list::<Shared<locus_kernel::Curve>>(0)?;
            let mut sections = Vec::with_capacity(list.len());
            let mut nulls = 0;
            for (k, c) in list.iter().enumerate() {
                match c {
                    Some(c) => sections.push(valid_nurbs(c, &format!("C (curve {k})"))?),
                    None => nulls += 1,
                }
            }
            if nulls > 0 {
                s.warning(format!("input C: {nulls} null item(s) left out"));
            }
            if options.adjust {
                sections = align_loft_sections(&sections)?;
            }
            let surface = NurbsSurface::loft(&sections, options.kind, options.closed)?;
            s.set(0, Shared::new(Brep::from_surface(surface)?));
            Ok(())
        })
}

/// Revolution \[RevSrf\]: a profile curve revolved about an axis.
pub fn revolution() -> NodeType {
    surface_node(REVOLUTION, "Revolution", "RevSrf", "Freeform")
        .gh_guid("cdee962f-4202-456b-a1b4-f3ed9aa0dc29")
        .description(
            "Revolves a profile curve about an axis line through an angle domain (radians, \
             counter-clockwise about the line's direction), in exact rational form: each \
             control point sweeps a circular arc of quadratic pieces up to 90° each. u is the \
             angle on the domain and v the profile's parameter. The domain must increase by \
             more than 0 and at most 2π; a zero-length axis is an error.",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("The profile curve."))
        .input(
            Port::new("Axis", "A", DataType::Line)
                .doc("The revolution axis: the line through its start along its direction."),
        )
        .input(
            Port::new("Domain", "D", DataType::Domain)
                .default_value(Interval::new(0.0, std::f64::consts::TAU))
                .doc("The angle domain in radians. Default 0 to 2π (a full turn)."),
        )
        .output(Port::new("Surface", "S", DataType::Surface).doc("The surface of revolution."))
        .lift3(
            |c: &Shared<locus_kernel::Curve>, axis: &Line, d: &Interval| {
                let profile = valid_nurbs(c, "C")?;
                let direction = axis.to - axis.from;
                if direction.length() == 0.0 || !direction.is_finite() {
                    return Err(NodeError::from("input A: the axis has no direction"));
                }
                Ok(Shared::new(NurbsSurface::revolution(
                    &profile, axis.from, direction, *d,
                )?))
            },
        )
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Circle, Curve, Line, Plane, Point3, SurfaceDirection, Vector3};
    use locus_runtime::{DataTree, Level, NodeCall, NodeCallResult, Value};

    use super::*;

    fn circle(z: f64, r: f64) -> Shared<Curve> {
        let plane = Plane::WORLD_XY.translated(Vector3::new(0.0, 0.0, z));
        Shared::new(Curve::from(Circle::new(plane, r).unwrap()))
    }

    fn line(a: Point3, b: Point3) -> Shared<Curve> {
        Shared::new(Curve::from(Line::new(a, b)))
    }

    fn error(r: &NodeCallResult) -> String {
        r.messages
            .iter()
            .find(|m| m.level == Level::Error)
            .map(|m| m.text.clone())
            .unwrap_or_default()
    }

    #[test]
    fn ruled_surface_between_two_lines_is_a_rectangle() {
        let r = NodeCall::new(&ruled_surface())
            .input(DataTree::from_item(line(
                Point3::ORIGIN,
                Point3::new(4.0, 0.0, 0.0),
            )))
            .input(DataTree::from_item(line(
                Point3::new(0.0, 3.0, 0.0),
                Point3::new(4.0, 3.0, 0.0),
            )))
            .run();
        let Some(Value::Surface(s)) = r.outputs[0].values().next().flatten() else {
            panic!("{:?}", r.messages)
        };
        assert!((s.area_properties().unwrap().area - 12.0).abs() < 1e-12);
        assert!(
            s.point_at(1.0, 1.0)
                .abs_diff_eq(Point3::new(4.0, 3.0, 0.0), 1e-12)
        );
    }

    #[test]
    fn straight_loft_of_two_circles_is_a_cylinder() {
        let r = NodeCall::new(&loft())
            .input(DataTree::from_list(vec![
                circle(0.0, 1.0),
                circle(2.0, 1.0),
            ]))
            .input(DataTree::from_item("straight".to_string()))
            .run();
        let Some(Value::Brep(b)) = r.outputs[0].values().next().flatten() else {
            panic!("{:?}", r.messages)
        };
        let area = b.area().unwrap();
        assert!((area - 4.0 * std::f64::consts::PI).abs() < 1e-9, "{area}");
    }

    #[test]
    fn normal_loft_passes_through_its_sections() {
        let sections = vec![circle(0.0, 1.0), circle(1.0, 2.0), circle(3.0, 1.0)];
        let r = NodeCall::new(&loft())
            .input(DataTree::from_list(sections))
            .run();
        let Some(Value::Brep(b)) = r.outputs[0].values().next().flatten() else {
            panic!("{:?}", r.messages)
        };
        let s = &b.faces()[0].surface;
        assert_eq!(s.degree_v(), 2);
        let first = s.isocurve(SurfaceDirection::U, 0.0).unwrap();
        assert!((first.point_at(0.3).to_vector().length() - 1.0).abs() < 1e-12);
    }

    #[test]
    fn revolved_line_is_a_cylinder() {
        let axis = Line::new(Point3::ORIGIN, Point3::new(0.0, 0.0, 1.0));
        let r = NodeCall::new(&revolution())
            .input(DataTree::from_item(line(
                Point3::new(2.0, 0.0, 0.0),
                Point3::new(2.0, 0.0, 3.0),
            )))
            .input(DataTree::from_item(axis))
            .run();
        let Some(Value::Surface(s)) = r.outputs[0].values().next().flatten() else {
            panic!("{:?}", r.messages)
        };
        let area = s.area_properties().unwrap().area;
        assert!((area - 12.0 * std::f64::consts::PI).abs() < 1e-9, "{area}");
        let r = NodeCall::new(&revolution())
            .input(DataTree::from_item(line(
                Point3::ORIGIN,
                Point3::new(1.0, 0.0, 0.0),
            )))
            .input(DataTree::from_item(Line::new(
                Point3::ORIGIN,
                Point3::ORIGIN,
            )))
            .run();
        assert!(error(&r).contains("direction"), "{:?}", r.messages);
    }

    #[test]
    fn bad_lofts_are_errors() {
        let r = NodeCall::new(&loft())
            .input(DataTree::from_list(vec![circle(0.0, 1.0)]))
            .run();
        assert!(error(&r).contains("at least"), "{:?}", r.messages);
        let r = NodeCall::new(&loft())
            .input(DataTree::from_list(vec![
                circle(0.0, 1.0),
                circle(1.0, 1.0),
            ]))
            .input(DataTree::from_item("developable".to_string()))
            .run();
        assert!(error(&r).contains("developable"), "{:?}", r.messages);
    }

    #[test]
    fn loft_options_write_the_words_loft_reads() {
        let run = |closed: bool, adjust: bool, kind: i64| {
            NodeCall::new(&loft_options_node())
                .input(DataTree::from_item(closed))
                .input(DataTree::from_item(adjust))
                .skip_input()
                .skip_input()
                .input(DataTree::from_item(kind))
                .run()
        };
        for (kind, word) in [
            (0, "normal"),
            (1, "loose"),
            (2, "tight"),
            (3, "straight"),
            (5, "uniform"),
        ] {
            let r = run(true, kind % 2 == 0, kind);
            let text: String = crate::test_support::only(&r, 0);
            let want = if kind % 2 == 0 {
                format!("{word} closed adjust")
            } else {
                format!("{word} closed")
            };
            assert_eq!(text, want);
            let parsed = loft_options(&text).unwrap();
            assert_eq!(options_text(parsed), text);
        }
        assert!(error(&run(false, true, 4)).contains("developable"));
        assert!(error(&run(false, true, 9)).contains("not a loft type"));
        let r = NodeCall::new(&loft_options_node())
            .skip_input()
            .skip_input()
            .input(DataTree::from_item(12_i64))
            .run();
        assert!(error(&r).contains("Rbd"), "{:?}", r.messages);
        // Defaults: open, adjusted, normal.
        let r = NodeCall::new(&loft_options_node()).run();
        assert_eq!(crate::test_support::only::<String>(&r, 0), "normal adjust");
    }

    /// A straight loft from a circle to the same circle run backwards is twisted through the
    /// axis; with `adjust` the second circle is turned round and the loft is a cylinder.
    #[test]
    fn adjusted_lofts_align_directions_and_seams() {
        let backwards = Shared::new(circle(2.0, 1.0).reversed());
        let area = |options: &str| {
            let r = NodeCall::new(&loft())
                .input(DataTree::from_list(vec![
                    circle(0.0, 1.0),
                    backwards.clone(),
                ]))
                .input(DataTree::from_item(options.to_string()))
                .run();
            let Some(Value::Brep(b)) = r.outputs[0].values().next().flatten() else {
                panic!("{:?}", r.messages)
            };
            b.area().unwrap()
        };
        let cylinder = 4.0 * std::f64::consts::PI;
        assert!((area("straight adjust") - cylinder).abs() < 1e-9);
        assert!((area("straight") - cylinder).abs() > 0.1);
    }
}
