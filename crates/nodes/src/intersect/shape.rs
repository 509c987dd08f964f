//! Intersect › Shape: solid booleans and splits of B-reps (Solid Union, Solid Difference, Split
//! Brep), and Point In Brep, on the kernel's [`Brep::boolean`], [`Brep::split_by_brep`] and
//! [`Brep::contains_point`], within the intersection tolerance.

use locus_kernel::{BooleanOperation, Brep, BrepContainment, Point3};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Solve};

use super::INTERSECTION_TOLERANCE;
use crate::surface::brep::brep_item;

/// Id of [`solid_union`].
pub const SOLID_UNION: &str = "intersect.solid_union";
/// Id of [`solid_difference`].
pub const SOLID_DIFFERENCE: &str = "intersect.solid_difference";
/// Id of [`split_brep`].
pub const SPLIT_BREP: &str = "intersect.split_brep";
/// Id of [`point_in_brep`].
pub const POINT_IN_BREP: &str = "surface.point_in_brep";

/// Registers the nodes of this file.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        solid_union(),
        solid_difference(),
        split_brep(),
        point_in_brep(),
    ] {
        registry.register(t);
    }
}

/// The closed B-reps of list input `input`: nulls are left out with a warning, a B-rep that is
/// not finite or not closed is an error naming its index.
fn solids(s: &mut Solve<'_>, input: usize, port: &str) -> Result<Vec<Brep>, NodeError> {
    let list = s.list::<Shared<Brep>>(input)?;
    let mut out = Vec::with_capacity(list.len());
    let mut nulls = 0;
    for (i, b) in list.iter().enumerate() {
        let Some(b) = b else {
            nulls += 1;
            continue;
        };
        let finite = b.vertices().iter().all(|v| v.point.is_finite())
            && b.faces().iter().all(|f| f.surface.is_finite());
        if !finite {
            return Err(format!("input {port}, item {i}: a coordinate is not finite").into());
        }
        if !b.is_solid() {
            return Err(format!(
                "input {port}, item {i}: the B-rep is not closed; solid booleans need closed \
                 B-reps (Cap Holes closes planar openings)"
            )
            .into());
        }
        out.push((**b).clone());
    }
    if nulls > 0 {
        s.warning(format!("input {port}: {nulls} null item(s) left out"));
    }
    Ok(out)
}

/// Whether the boxes of two B-reps meet within the intersection tolerance: only then can the
/// B-reps cross.
fn boxes_meet(a: &Brep, b: &Brep) -> bool {
    let (a, b) = (a.bounding_box(), b.bounding_box());
    let t = INTERSECTION_TOLERANCE;
    a.min.x <= b.max.x + t
        && b.min.x <= a.max.x + t
        && a.min.y <= b.max.y + t
        && b.min.y <= a.max.y + t
        && a.min.z <= b.max.z + t
        && b.min.z <= a.max.z + t
}

/// Warns when a result did not close up (faces lying on each other, or a cut the kernel
/// could not follow).
fn warn_open(s: &mut Solve<'_>, result: &[Brep]) {
    let open = result.iter().filter(|b| !b.is_solid()).count();
    if open > 0 {
        s.warning(format!(
            "{open} result(s) did not close up into a solid (faces lying on each other are \
             not split along their overlap); they are returned open"
        ));
    }
}

/// Solid Union \[SUnion\]: the union of closed B-reps.
pub fn solid_union() -> NodeType {
    NodeType::new(SOLID_UNION, "Solid Union", "SUnion", "Intersect")
        .subcategory("Shape")
        .gh_guid("10434a15-da85-4281-bb64-a2b3a995b9c6")
        .description(
            "Joins closed B-reps into the solid that holds everything inside any of them: every \
             face is split where the other B-reps cross it (within the intersection tolerance, \
             0.001), the pieces outside the others are kept and joined. B-reps that do not \
             meet stay separate results. A B-rep that is not closed is an error.",
        )
        .input(
            Port::new("Breps", "B", DataType::Brep)
                .doc("The closed B-reps to unite (a list).")
                .list(),
        )
        .output(
            Port::new("Result", "R", DataType::Brep)
                .doc("The union: one B-rep per separate solid.")
                .list(),
        )
        .solve(|s| {
            let breps = solids(s, 0, "B")?;
            let mut parts: Vec<Brep> = Vec::new();
            for b in breps {
                let mut current = b;
                let mut rest = Vec::new();
                for p in parts {
                    if !boxes_meet(&current, &p) {
                        rest.push(p);
                        continue;
                    }
                    let mut u =
                        current.boolean(&p, BooleanOperation::Union, INTERSECTION_TOLERANCE)?;
                    if u.len() == 1 && u[0].is_solid() {
                        current = u.remove(0);
                    } else {
                        // They touch without merging: keep both as they were.
                        rest.push(p);
                    }
                }
                rest.push(current);
                parts = rest;
            }
            warn_open(s, &parts);
            s.set_list(0, parts.into_iter().map(Shared::new).collect());
            Ok(())
        })
}

/// Solid Difference \[SDiff\]: closed B-reps with others taken away.
pub fn solid_difference() -> NodeType {
    NodeType::new(SOLID_DIFFERENCE, "Solid Difference", "SDiff", "Intersect")
        .subcategory("Shape")
        .gh_guid("fab11c30-2d9c-4d15-ab3c-2289f1ae5c21")
        .description(
            "Takes the closed B-reps of B away from each closed B-rep of A: faces are split \
             where the B-reps cross (within the intersection tolerance, 0.001), the pieces of A \
             outside B are kept with the pieces of B inside A turned over, and joined. A part of \
             B wholly inside A becomes a cavity. A B-rep that is not closed is an error.",
        )
        .input(
            Port::new("Breps A", "A", DataType::Brep)
                .doc("The closed B-reps to take away from (a list).")
                .list(),
        )
        .input(
            Port::new("Breps B", "B", DataType::Brep)
                .doc("The closed B-reps to take away (a list).")
                .list(),
        )
        .output(
            Port::new("Result", "R", DataType::Brep)
                .doc("What is left of A, one B-rep per separate solid.")
                .list(),
        )
        .solve(|s| {
            let a = solids(s, 0, "A")?;
            let b = solids(s, 1, "B")?;
            let mut out = Vec::new();
            for solid in a {
                let mut parts = vec![solid];
                for cutter in &b {
                    let mut next = Vec::new();
                    for p in parts {
                        if boxes_meet(&p, cutter) {
                            next.extend(p.boolean(
                                cutter,
                                BooleanOperation::Difference,
                                INTERSECTION_TOLERANCE,
                            )?);
                        } else {
                            next.push(p);
                        }
                    }
                    parts = next;
                }
                out.extend(parts);
            }
            warn_open(s, &out);
            s.set_list(0, out.into_iter().map(Shared::new).collect());
            Ok(())
        })
}

/// Split Brep \[Split\]: a B-rep cut into pieces by another.
pub fn split_brep() -> NodeType {
    NodeType::new(SPLIT_BREP, "Split Brep", "Split", "Intersect")
        .subcategory("Shape")
        .gh_guid("ef6b26f4-f820-48d6-b0c5-85898ef8888b")
        .description(
            "Splits a B-rep where a cutter B-rep crosses it (within the intersection tolerance, \
             0.001): its faces are split along the intersection curves and the pieces that \
             stay connected across the B-rep's own edges are joined. A cutter that does not \
             cut it gives the B-rep back whole.",
        )
        .input(
            Port::new("Brep", "B", DataType::Brep)
                .doc("The B-rep to split. Boxes and surfaces are taken as B-reps."),
        )
        .input(
            Port::new("Cutter", "C", DataType::Brep)
                .doc("The B-rep to split with. Boxes and surfaces are taken as B-reps."),
        )
        .output(
            Port::new("Result", "R", DataType::Brep)
                .doc("The pieces.")
                .list(),
        )
        .solve(|s| {
            let b = brep_item(s, 0)?;
            let cutter = brep_item(s, 1)?;
            let pieces = b.split_by_brep(&cutter, INTERSECTION_TOLERANCE)?;
            s.set_list(0, pieces.into_iter().map(Shared::new).collect());
            Ok(())
        })
}

/// Point In Brep \[BrepInc\]: whether a point lies inside a closed B-rep.
pub fn point_in_brep() -> NodeType {
    NodeType::new(POINT_IN_BREP, "Point In Brep", "BrepInc", "Surface")
        .subcategory("Analysis")
        .gh_guid("e03561f8-0e66-41d3-afde-62049f152443")
        .description(
            "Tests whether a point lies inside a closed B-rep, by the parity of a ray's \
             crossings (rays that graze a face or an edge are replaced by others). A point within \
             the intersection tolerance (0.001) of the boundary counts as inside unless Strict \
             is set. A B-rep that is not closed has no inside and is an error.",
        )
        .input(Port::new("Brep", "B", DataType::Brep).doc("The closed B-rep."))
        .input(Port::new("Point", "P", DataType::Point).doc("The point to test."))
        .input(
            Port::new("Strict", "S", DataType::Boolean)
                .doc("If true, a point on the boundary is not inside.")
                .default_value(false),
        )
        .output(Port::new("Inside", "I", DataType::Boolean).doc("Whether the point is inside."))
        .solve(|s| {
            let b = brep_item(s, 0)?;
            let p = *s.item::<Point3>(1)?;
            let strict = *s.item::<bool>(2)?;
            let at = b.contains_point(p, INTERSECTION_TOLERANCE)?;
            let inside = match at {
                BrepContainment::Inside => true,
                BrepContainment::OnBoundary => !strict,
                BrepContainment::Outside => false,
            };
            s.set(0, inside);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{assert_clean, assert_error, items};
    use locus_kernel::{Interval, OrientedBox, Plane, Sphere};
    use locus_runtime::{DataTree, NodeCall};

    fn cube(lo: f64, hi: f64) -> Shared<Brep> {
        let i = Interval::new(lo, hi);
        Shared::new(Brep::from_box(&OrientedBox::new(Plane::WORLD_XY, i, i, i)).unwrap())
    }

    fn volumes(t: &DataTree) -> Vec<f64> {
        items::<Shared<Brep>>(t)
            .into_iter()
            .map(|b| b.unwrap().volume().unwrap())
            .collect()
    }

    #[test]
    fn union_of_three_cubes_two_overlapping() {
        let r = NodeCall::new(&solid_union())
            .input(DataTree::from_list(vec![
                cube(0.0, 2.0),
                cube(1.0, 3.0),
                cube(10.0, 11.0),
            ]))
            .run();
        assert_clean(&r);
        let mut v = volumes(&r.outputs[0]);
        v.sort_by(f64::total_cmp);
        assert_eq!(v.len(), 2);
        assert!(
            (v[0] - 1.0).abs() < 1e-9 && (v[1] - 15.0).abs() < 1e-9,
            "{v:?}"
        );
    }

    #[test]
    fn difference_takes_every_b_from_every_a() {
        let r = NodeCall::new(&solid_difference())
            .input(DataTree::from_list(vec![cube(0.0, 2.0)]))
            .input(DataTree::from_list(vec![cube(1.0, 3.0), cube(-1.0, 0.5)]))
            .run();
        assert_clean(&r);
        let v = volumes(&r.outputs[0]);
        // 8 − 1 − 0.125, the two corners taken away do not overlap.
        assert_eq!(v.len(), 1);
        assert!((v[0] - 6.875).abs() < 1e-9, "{v:?}");
    }

    #[test]
    fn open_breps_are_reported() {
        let face = Shared::new(cube(0.0, 1.0).extract_face(0).unwrap());
        let r = NodeCall::new(&solid_union())
            .input(DataTree::from_list(vec![cube(0.0, 1.0), face]))
            .run();
        assert_error(&r, "item 1: the B-rep is not closed");
    }

    #[test]
    fn split_and_point_in_brep() {
        let r = NodeCall::new(&split_brep())
            .input(DataTree::from_item(cube(0.0, 2.0)))
            .input(DataTree::from_item(cube(1.0, 3.0)))
            .run();
        assert_clean(&r);
        // The cube's boundary split into the corner inside the cutter and the rest.
        let areas: Vec<f64> = items::<Shared<Brep>>(&r.outputs[0])
            .into_iter()
            .map(|b| b.unwrap().area().unwrap())
            .collect();
        assert_eq!(areas.len(), 2);
        assert!((areas.iter().sum::<f64>() - 24.0).abs() < 1e-9, "{areas:?}");
        let ball =
            Shared::new(Brep::from_sphere(&Sphere::new(Point3::ORIGIN, 1.0).unwrap()).unwrap());
        for (p, strict, expected) in [
            (Point3::new(0.5, 0.0, 0.0), false, true),
            (Point3::new(1.0, 0.0, 0.0), false, true),
            (Point3::new(1.0, 0.0, 0.0), true, false),
            (Point3::new(2.0, 0.0, 0.0), false, false),
        ] {
            let r = NodeCall::new(&point_in_brep())
                .input(DataTree::from_item(ball.clone()))
                .input(DataTree::from_item(p))
                .input(DataTree::from_item(strict))
                .run();
            assert_clean(&r);
            assert_eq!(items::<bool>(&r.outputs[0]), vec![Some(expected)], "{p:?}");
        }
        let r = NodeCall::new(&point_in_brep())
            .input(DataTree::from_item(Shared::new(
                cube(0.0, 1.0).extract_face(0).unwrap(),
            )))
            .input(DataTree::from_item(Point3::ORIGIN))
            .run();
        assert_error(&r, "not closed");
    }
}
