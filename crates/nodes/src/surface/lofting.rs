//! Surface › Freeform: Ruled Surface and Loft, surfaces through curves.
//!
//! Both make their curves compatible first (the kernel's `NurbsCurve::make_compatible`: each
//! reparameterized to `0..1`, raised to the highest degree among them, with all their knots
//! merged), so `u` runs along the curves on `0..1`. Curve directions and closed curves' seams
//! are taken as given (Rhino's Loft can align them; locus does not).
//!
//! Grasshopper's Loft takes a Loft Options object from its Loft Options component, which
//! locus does not have; here the Options input is a text of words instead: `normal` or
//! `straight` for the type and `closed` to join the last section back to the first.

use locus_kernel::{Brep, Interval, Line, LoftType, NurbsCurve, NurbsSurface};
use locus_runtime::{DataType, NodeError, NodeType, Port, Shared};

use super::brep::surface_node;

/// Id of [`ruled_surface`].
pub const RULED_SURFACE: &str = "surface.ruled_surface";
/// Id of [`loft`].
pub const LOFT: &str = "surface.loft";
/// Id of [`revolution`].
pub const REVOLUTION: &str = "surface.revolution";

/// Registers Ruled Surface and Loft.
pub fn register(registry: &mut locus_runtime::NodeRegistry) {
    registry.register(ruled_surface());
    registry.register(loft());
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

/// The loft type and closure from the Options text.
fn loft_options(text: &str) -> Result<(LoftType, bool), NodeError> {
    let (mut kind, mut closed) = (LoftType::Normal, false);
    for word in text
        .split(|c: char| c.is_whitespace() || c == ',' || c == ';')
        .filter(|w| !w.is_empty())
    {
        match word.to_ascii_lowercase().as_str() {
            "normal" => kind = LoftType::Normal,
            "straight" => kind = LoftType::Straight,
            "closed" => closed = true,
            "open" => closed = false,
            other => {
                return Err(NodeError(format!(
                    "input O: unknown loft option `{other}`; use normal, straight, open or \
                     closed (loose, tight, developable and uniform lofts are not supported)"
                )));
            }
        }
    }
    Ok((kind, closed))
}

/// Loft \[Loft\]: a surface through section curves.
pub fn loft() -> NodeType {
    surface_node(LOFT, "Loft", "Loft", "Freeform")
        .gh_guid("a7a41d0a-2188-4f7a-82cc-1a2c4e4ec850")
        .description(
            "Creates a surface through a list of section curves, as a one-face B-rep. The \
             sections are made compatible (each on 0 to 1, the highest degree, merged knots) \
             and their control points are interpolated across them: a normal loft is cubic \
             (degree sections − 1 below four sections), a straight loft degree 1. Sections \
             get averaged chord-length parameters on 0 to 1 across; u runs along the sections, \
             v across, and the surface passes through every section. A closed loft joins the \
             last section back to the first (normal closed lofts are only continuous, not \
             smooth, at that seam). Curve directions and seams are used as given.",
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
                    "Loft options as words: `normal` or `straight`, and `closed` to close the \
                     loft. Default `normal` (open). Grasshopper's Loft Options object is not \
                     supported.",
                ),
        )
        .output(Port::new("Loft", "L", DataType::Brep).doc("The loft, a one-face B-rep."))
        .solve(|s| {
            let (kind, closed) = loft_options(s.item::<String>(1)?)?;
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
            let surface = NurbsSurface::loft(&sections, kind, closed)?;
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
            .input(DataTree::from_item("tight".to_string()))
            .run();
        assert!(error(&r).contains("tight"));
    }
}
