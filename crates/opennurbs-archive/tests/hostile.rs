//! Property tests: random, truncated and mutated bytes never panic the reader (they decode or
//! give an error), and random valid geometry round-trips exactly.

use base64::Engine as _;
use locus_kernel::{Color, Curve, Mesh, MeshFace, NurbsCurve, NurbsSurface, Point3, Vector3};
use locus_opennurbs_archive::{Geometry, decode, decode_json, encode};
use proptest::prelude::*;

/// Valid encodings to damage: every golden file (rhino3dm's bytes) plus locus's own.
fn seeds() -> Vec<Vec<u8>> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/golden");
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let text = std::fs::read_to_string(e.unwrap().path()).unwrap();
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        let data = v["encoded"]["data"].as_str().unwrap();
        out.push(
            base64::engine::general_purpose::STANDARD
                .decode(data)
                .unwrap(),
        );
    }
    out.sort_by_key(Vec::len);
    out
}

fn point() -> impl Strategy<Value = Point3> {
    (-1e3..1e3f64, -1e3..1e3f64, -1e3..1e3f64).prop_map(|(x, y, z)| Point3::new(x, y, z))
}

fn nurbs_curve() -> impl Strategy<Value = NurbsCurve> {
    (1usize..=5, 0usize..6, any::<bool>()).prop_flat_map(|(degree, extra, rational)| {
        let n = degree + 1 + extra;
        (
            prop::collection::vec(point(), n),
            prop::collection::vec(
                if rational {
                    0.1..10.0f64
                } else {
                    1.0..1.0000001f64
                },
                n,
            ),
            prop::collection::vec(0.01..2.0f64, n + degree - 2),
        )
            .prop_map(move |(points, weights, steps)| {
                // Increasing knots with clamped ends: multiplicity `degree` at both ends.
                let mut knots = vec![0.0; degree];
                let mut t = 0.0;
                for s in &steps[..n - degree - 1] {
                    t += s;
                    knots.push(t);
                }
                t += 1.0;
                knots.extend(std::iter::repeat_n(t, degree));
                let weights = if rational { weights } else { vec![1.0; n] };
                NurbsCurve::new(degree, points, weights, knots).unwrap()
            })
    })
}

fn mesh() -> impl Strategy<Value = Mesh> {
    (3usize..300).prop_flat_map(|n| {
        (
            prop::collection::vec(point(), n),
            prop::collection::vec(
                (0..n as u32, 0..n as u32, 0..n as u32, any::<bool>()),
                1..40,
            ),
            any::<bool>(),
            any::<bool>(),
        )
            .prop_map(move |(vs, fs, with_normals, with_colors)| {
                let faces: Vec<MeshFace> = fs
                    .into_iter()
                    .filter(|&(a, b, c, _)| a != b && b != c && a != c)
                    .map(|(a, b, c, _)| MeshFace::triangle(a, b, c))
                    .collect();
                let mut m = Mesh::new(vs, faces).unwrap();
                if with_normals {
                    m = m
                        .with_normals(vec![Vector3::new(0.0, 0.0, 1.0); n])
                        .unwrap();
                }
                if with_colors {
                    let cs = (0..n)
                        .map(|i| Color::rgba(i as u8, 3, (i * 7) as u8, 200))
                        .collect();
                    m = m.with_colors(cs).unwrap();
                }
                m
            })
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn random_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..600)) {
        let _ = decode(&bytes);
    }

    #[test]
    fn truncated_archives_are_errors(seed in 0usize..64, cut in 0.0..1.0f64) {
        let seeds = seeds();
        let bytes = &seeds[seed % seeds.len()];
        let n = ((bytes.len() as f64) * cut) as usize;
        prop_assert!(decode(&bytes[..n.min(bytes.len() - 1)]).is_err());
    }

    #[test]
    fn mutated_archives_never_panic(
        seed in 0usize..64,
        edits in prop::collection::vec((0.0..1.0f64, any::<u8>()), 1..6),
    ) {
        let seeds = seeds();
        let mut bytes = seeds[seed % seeds.len()].clone();
        for (at, b) in edits {
            let i = ((bytes.len() as f64) * at) as usize % bytes.len();
            bytes[i] = b;
        }
        let _ = decode(&bytes);
    }

    #[test]
    fn curves_round_trip(c in nurbs_curve()) {
        let g = Geometry::Curve(Curve::Nurbs(c.clone()));
        let Geometry::Curve(Curve::Nurbs(back)) = decode(&encode(&g).unwrap()).unwrap() else { panic!() };
        if c.is_rational() {
            // Homogeneous storage: w·x / w may differ from x in the last bit.
            prop_assert_eq!(back.knots(), c.knots());
            prop_assert_eq!(back.weights(), c.weights());
            for (p, q) in c.points().iter().zip(back.points()) {
                prop_assert!(p.distance(*q) <= 1e-12 * (1.0 + p.distance(Point3::ORIGIN)));
            }
        } else {
            prop_assert_eq!(back, c);
        }
    }

    #[test]
    fn surfaces_round_trip_exactly(a in nurbs_curve(), b in nurbs_curve(), w in 0.2..5.0f64) {
        // A surface with a's knots in u and b's in v, control points from both.
        let (nu, nv) = (a.point_count(), b.point_count());
        let points = (0..nu * nv).map(|k| a.points()[k / nv] + (b.points()[k % nv] - Point3::ORIGIN)).collect();
        let weights = (0..nu * nv).map(|k| if k % 3 == 0 { w } else { 1.0 }).collect();
        let s = NurbsSurface::from_flat(
            [a.degree(), b.degree()], [nu, nv], points, weights,
            [a.knots().to_vec(), b.knots().to_vec()],
        ).unwrap();
        let g = Geometry::Surface(s);
        let back = decode(&encode(&g).unwrap()).unwrap();
        // Homogeneous storage: w·x / w may differ from x in the last bit.
        let (Geometry::Surface(s), Geometry::Surface(t)) = (&g, &back) else { panic!() };
        prop_assert_eq!(s.knots_u(), t.knots_u());
        prop_assert_eq!(s.weights(), t.weights());
        for (p, q) in s.points().iter().zip(t.points()) {
            prop_assert!(p.distance(*q) <= 1e-12 * (1.0 + p.distance(Point3::ORIGIN)));
        }
    }

    #[test]
    fn meshes_round_trip_exactly_except_float_normals(m in mesh()) {
        let g = Geometry::Mesh(m.clone());
        let Geometry::Mesh(back) = decode(&encode(&g).unwrap()).unwrap() else { panic!() };
        prop_assert_eq!(back.vertices(), m.vertices());
        prop_assert_eq!(back.faces(), m.faces());
        prop_assert_eq!(back.colors(), m.colors());
        prop_assert_eq!(back.normals().is_some(), m.normals().is_some());
    }

    #[test]
    fn malformed_json_is_an_error(s in ".{0,80}", n in any::<i64>()) {
        let v = serde_json::json!({"version": 10000, "archive3dm": n, "opennurbs": n, "data": s});
        let _ = decode_json(&v);
        prop_assert!(decode_json(&serde_json::json!(s)).is_err());
    }
}

#[test]
fn huge_counts_fail_fast_without_allocating() {
    // A mesh header claiming 2^31 − 1 faces and vertices in a few bytes.
    let Geometry::Mesh(m) = decode(
        &encode(&Geometry::Mesh(
            Mesh::new(
                vec![
                    Point3::ORIGIN,
                    Point3::new(1.0, 0.0, 0.0),
                    Point3::new(0.0, 1.0, 0.0),
                ],
                vec![MeshFace::triangle(0, 1, 2)],
            )
            .unwrap(),
        ))
        .unwrap(),
    )
    .unwrap() else {
        panic!()
    };
    assert_eq!(m.vertices().len(), 3);
    let mut bytes = encode(&Geometry::Mesh(m)).unwrap();
    // vertex count sits right after the data chunk header and the version byte.
    let at = 12 + 32 + 12 + 1;
    bytes[at..at + 4].copy_from_slice(&i32::MAX.to_le_bytes());
    bytes[at + 4..at + 8].copy_from_slice(&i32::MAX.to_le_bytes());
    let err = decode(&bytes).unwrap_err().to_string();
    assert!(err.contains("limit") || err.contains("truncated"), "{err}");
}
