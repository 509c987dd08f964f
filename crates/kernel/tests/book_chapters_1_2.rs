//! The worked numbers of chapters 1 (vector mathematics) and 2 (matrices and transformations)
//! of *Essential Mathematics for Computational Design* (`shared/seed/`), in the book's order.

use std::f64::consts::PI;

use locus_kernel::{BoundingBox, Plane, Point3, Transform, Vector3};

fn assert_rows(t: &Transform, expected: [[f64; 4]; 4], tolerance: f64) {
    let rows = t.to_rows();
    for i in 0..4 {
        for j in 0..4 {
            assert!(
                (rows[i][j] - expected[i][j]).abs() <= tolerance,
                "entry [{i}][{j}] is {} not {}",
                rows[i][j],
                expected[i][j]
            );
        }
    }
}

// Chapter 1: vector mathematics.

#[test]
fn vector_representation_tip_point() {
    // A = (1,2,3), v = <5,6,7>, B = A + v = (6,8,10).
    let a = Point3::new(1.0, 2.0, 3.0);
    let v = Vector3::new(5.0, 6.0, 7.0);
    assert_eq!(a + v, Point3::new(6.0, 8.0, 10.0));
    // The position vector of B has B's coordinates.
    assert_eq!(
        (a + v).to_vector(),
        Point3::new(6.0, 8.0, 10.0) - Point3::ORIGIN
    );
}

#[test]
fn vector_length_and_unit_vector() {
    // |<4,3,0>| = 5 and its unit vector is <0.8,0.6,0>, of length 1.
    let a = Vector3::new(4.0, 3.0, 0.0);
    assert_eq!(a.length(), 5.0);
    let b = a.unitize().unwrap();
    assert!(b.abs_diff_eq(Vector3::new(0.8, 0.6, 0.0), 1e-16));
    assert!((b.length() - 1.0).abs() < 1e-16);
}

#[test]
fn vector_scalar_addition_subtraction() {
    // 2 * <4,3,0> = <8,6,0>.
    assert_eq!(
        2.0 * Vector3::new(4.0, 3.0, 0.0),
        Vector3::new(8.0, 6.0, 0.0)
    );
    // <1,2,0> + <4,1,3> = <5,3,3>.
    assert_eq!(
        Vector3::new(1.0, 2.0, 0.0) + Vector3::new(4.0, 1.0, 3.0),
        Vector3::new(5.0, 3.0, 3.0)
    );
    // a = <1,2,0>, b = <4,1,4>: a − b = <−3,1,−4>, b − a = <3,−1,4>, of equal length.
    let a = Vector3::new(1.0, 2.0, 0.0);
    let b = Vector3::new(4.0, 1.0, 4.0);
    assert_eq!(a - b, Vector3::new(-3.0, 1.0, -4.0));
    assert_eq!(b - a, Vector3::new(3.0, -1.0, 4.0));
    assert_eq!((a - b).length(), (b - a).length());
}

#[test]
fn vector_properties() {
    // The eight properties, on the book's vectors and two numbers.
    let (a, b, c) = (
        Vector3::new(1.0, 2.0, 0.0),
        Vector3::new(4.0, 1.0, 3.0),
        Vector3::new(-2.0, 0.5, 7.0),
    );
    let (s, t) = (2.0, -3.0);
    assert_eq!(a + b, b + a);
    assert_eq!(a + Vector3::ZERO, a);
    assert_eq!(s * (a + b), s * a + s * b);
    assert_eq!((s * t) * a, s * (t * a));
    assert_eq!(a + (b + c), (a + b) + c);
    assert_eq!(a + (-a), Vector3::ZERO);
    assert_eq!((s + t) * a, s * a + t * a);
    assert_eq!(1.0 * a, a);
}

#[test]
fn dot_product() {
    // <1,2,3> · <5,6,7> = 38.
    assert_eq!(
        Vector3::new(1.0, 2.0, 3.0).dot(Vector3::new(5.0, 6.0, 7.0)),
        38.0
    );
    // Unit vectors <1,0,0> · <0.6,0.8,0> = 0.6, the cosine of the angle between them.
    let a = Vector3::X;
    let b = Vector3::new(0.6, 0.8, 0.0);
    assert_eq!(a.dot(b), 0.6);
    assert!((a.angle_to(b).unwrap().cos() - 0.6).abs() < 1e-15);
    // <0,3,4> · <0,3,4> = 25 = |a|².
    let a = Vector3::new(0.0, 3.0, 4.0);
    assert_eq!(a.dot(a), 25.0);
    assert_eq!(a.length().powi(2), 25.0);
    // The world x and y axes are orthogonal: x · y = 0.
    assert_eq!(Vector3::X.dot(Vector3::Y), 0.0);
    assert!(Vector3::X.is_perpendicular_to(Vector3::Y, 0.0));
    // Same general direction: positive; opposite: negative.
    assert!(Vector3::new(1.0, 1.0, 0.0).dot(Vector3::new(1.0, 0.2, 0.0)) > 0.0);
    assert!(Vector3::new(1.0, 1.0, 0.0).dot(Vector3::new(-1.0, 0.2, 0.0)) < 0.0);
}

#[test]
fn projection_length_by_dot_product() {
    // a = <5,2,0>, b = <9,0,0>: pL = a · unit(b) = 5·1 + 2·0 + 0·0. The book prints the result
    // as 2, a typo: the sum it writes out is 5, which is also |a| cos θ.
    let a = Vector3::new(5.0, 2.0, 0.0);
    let b = Vector3::new(9.0, 0.0, 0.0);
    assert_eq!(b.unitize().unwrap(), Vector3::X);
    assert_eq!(a.projection_length_onto(b).unwrap(), 5.0);
    let by_angle = a.length() * a.angle_to(b).unwrap().cos();
    assert!((by_angle - 5.0).abs() < 1e-14);
}

#[test]
fn dot_product_properties() {
    let (a, b, c) = (
        Vector3::new(1.0, 2.0, 3.0),
        Vector3::new(5.0, 6.0, 7.0),
        Vector3::new(-1.0, 0.5, 2.0),
    );
    let s = 3.0;
    assert_eq!(a.dot(a), a.length_squared());
    assert_eq!(a.dot(b + c), a.dot(b) + a.dot(c));
    assert_eq!(Vector3::ZERO.dot(a), 0.0);
    assert_eq!(a.dot(b), b.dot(a));
    assert_eq!((s * a).dot(b), s * a.dot(b));
    assert_eq!(a.dot(s * b), s * a.dot(b));
}

#[test]
fn cross_product() {
    // <3,1,0> × <1,2,0> = <0,0,5>, orthogonal to both.
    let a = Vector3::new(3.0, 1.0, 0.0);
    let b = Vector3::new(1.0, 2.0, 0.0);
    let c = a.cross(b);
    assert_eq!(c, Vector3::new(0.0, 0.0, 5.0));
    assert_eq!(c.dot(a), 0.0);
    assert_eq!(c.dot(b), 0.0);
    // x × y = z and y × x = −z (order matters, right-hand rule).
    assert_eq!(Vector3::X.cross(Vector3::Y), Vector3::Z);
    assert_eq!(Vector3::Y.cross(Vector3::X), -Vector3::Z);
    // |a × b| = |a||b| sin θ.
    let sine = a.angle_to(b).unwrap().sin();
    assert!((c.length() - a.length() * b.length() * sine).abs() < 1e-14);
    // Parallel vectors have a zero cross product.
    assert_eq!(a.cross(2.0 * a), Vector3::ZERO);
    assert!(a.is_parallel_to(2.0 * a, 0.0));
}

#[test]
fn cross_product_properties() {
    let (a, b, c) = (
        Vector3::new(1.0, 2.0, 3.0),
        Vector3::new(5.0, 6.0, 7.0),
        Vector3::new(-1.0, 0.5, 2.0),
    );
    let s = 2.0;
    assert_eq!(a.cross(b), -b.cross(a));
    assert_eq!((s * a).cross(b), s * a.cross(b));
    assert_eq!(a.cross(s * b), s * a.cross(b));
    assert_eq!(a.cross(b + c), a.cross(b) + a.cross(c));
    assert_eq!((a + b).cross(c), a.cross(c) + b.cross(c));
    assert_eq!(a.dot(b.cross(c)), a.cross(b).dot(c));
    assert_eq!(a.cross(b.cross(c)), a.dot(c) * b - a.dot(b) * c);
}

#[test]
fn vector_equation_of_a_line() {
    // P = Q + t v; x = x0 + t a, and so on.
    let q = Point3::new(1.0, -2.0, 0.5);
    let v = Vector3::new(3.0, 4.0, 0.0).unitize().unwrap();
    let t = 10.0;
    let p = q + t * v;
    assert!(p.abs_diff_eq(Point3::new(7.0, 6.0, 0.5), 1e-14));
    // The midpoint M = Q + 0.5 (P − Q), and in general M = Q + t (P − Q).
    let p = Point3::new(4.0, 6.0, 8.0);
    let q = Point3::new(2.0, 2.0, 2.0);
    assert_eq!(q + 0.5 * (p - q), Point3::new(3.0, 4.0, 5.0));
    assert_eq!(q.lerp(p, 0.5), q.midpoint(p));
    assert_eq!(q.lerp(p, 0.25), Point3::new(2.5, 3.0, 3.5));
}

#[test]
fn vector_equation_of_a_plane() {
    // n = (b − a) × (c − a) and the scalar equation a(x−x0) + b(y−y0) + c(z−z0) = 0.
    let a = Point3::new(1.0, 0.0, 0.0);
    let b = Point3::new(0.0, 1.0, 0.0);
    let c = Point3::new(0.0, 0.0, 1.0);
    let n = (b - a).cross(c - a);
    assert_eq!(n, Vector3::new(1.0, 1.0, 1.0));
    assert_eq!(n.dot(b - a), 0.0);
    let plane = Plane::from_points(a, b, c).unwrap();
    assert!(plane.normal().abs_diff_eq(n.unitize().unwrap(), 1e-15));
    // x + y + z − 1 = 0, scaled to the unit normal.
    let [ea, eb, ec, ed] = plane.equation();
    let k = 1.0 / 3f64.sqrt();
    for (got, want) in [(ea, k), (eb, k), (ec, k), (ed, -k)] {
        assert!((got - want).abs() < 1e-15, "{got} vs {want}");
    }
    for p in [a, b, c] {
        assert!(plane.value_at(p).abs() < 1e-15);
    }
}

#[test]
fn face_direction_tutorial() {
    // The sign of (point − closest point) · normal tells front from back.
    let plane = Plane::from_normal(Point3::new(0.0, 0.0, 1.0), Vector3::Z).unwrap();
    let front = Point3::new(2.0, 3.0, 4.0);
    let back = Point3::new(2.0, 3.0, -4.0);
    assert!((front - plane.closest_point(front)).dot(plane.normal()) > 0.0);
    assert!((back - plane.closest_point(back)).dot(plane.normal()) < 0.0);
}

#[test]
fn tangent_spheres_tutorial() {
    // D = A + t (B − A), C1 the midpoint of A and D, C2 that of D and B, r1 = |A C1|,
    // r2 = |B C2|, and the two spheres touch at D.
    let a = Point3::new(0.0, 0.0, 0.0);
    let b = Point3::new(10.0, 0.0, 0.0);
    let t = 0.3;
    let d = a + t * (b - a);
    let c1 = a + 0.5 * (d - a);
    let c2 = d + 0.5 * (b - d);
    let (r1, r2) = (a.distance(c1), b.distance(c2));
    assert!(d.abs_diff_eq(Point3::new(3.0, 0.0, 0.0), 1e-15));
    assert!((r1 - 1.5).abs() < 1e-15 && (r2 - 3.5).abs() < 1e-15);
    assert!((c1.distance(c2) - (r1 + r2)).abs() < 1e-14);
}

// Chapter 2: matrices and transformations.

#[test]
fn identity_matrix() {
    let m =
        Transform::rotation(0.4, Vector3::new(1.0, 2.0, 2.0), Point3::new(1.0, 1.0, 0.0)).unwrap();
    assert_eq!(Transform::IDENTITY * m, m);
    assert_eq!(m * Transform::IDENTITY, m);
    assert_rows(
        &Transform::IDENTITY,
        [
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
        0.0,
    );
}

#[test]
fn translation_matrix() {
    // P(2,3,1) moved by <2,2,2> is (4,5,3), by addition and by the matrix.
    let p = Point3::new(2.0, 3.0, 1.0);
    let v = Vector3::new(2.0, 2.0, 2.0);
    assert_eq!(p + v, Point3::new(4.0, 5.0, 3.0));
    let m = Transform::translation(v);
    assert_rows(
        &m,
        [
            [1.0, 0.0, 0.0, 2.0],
            [0.0, 1.0, 0.0, 2.0],
            [0.0, 0.0, 1.0, 2.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
        0.0,
    );
    assert_eq!(m.transform_point(p), Point3::new(4.0, 5.0, 3.0));
    // Vectors are not moved.
    assert_eq!(m.transform_vector(v), v);
    // The box moved by 4, 5 and 3: every corner moves by the same vector.
    let bx = BoundingBox::new(Point3::ORIGIN, Point3::new(1.0, 1.0, 1.0));
    let m = Transform::translation(Vector3::new(4.0, 5.0, 3.0));
    assert_rows(
        &m,
        [
            [1.0, 0.0, 0.0, 4.0],
            [0.0, 1.0, 0.0, 5.0],
            [0.0, 0.0, 1.0, 3.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
        0.0,
    );
    let moved = bx.transformed(&m);
    for (before, after) in bx.corners().iter().zip(moved.corners()) {
        assert_eq!(after - *before, Vector3::new(4.0, 5.0, 3.0));
    }
}

#[test]
fn rotation_matrices() {
    // x' = x cos b − y sin b, y' = x sin b + y cos b.
    let b = 0.5f64;
    let p = Point3::new(2.0, 1.0, 3.0);
    let r = Transform::rotation_z(b);
    let q = r.transform_point(p);
    assert!((q.x - (p.x * b.cos() - p.y * b.sin())).abs() < 1e-15);
    assert!((q.y - (p.x * b.sin() + p.y * b.cos())).abs() < 1e-15);
    assert_eq!(q.z, p.z);
    // The 30-degree rotation matrix, printed with two digits in the book.
    assert_rows(
        &Transform::rotation_z(30f64.to_radians()),
        [
            [0.87, -0.5, 0.0, 0.0],
            [0.5, 0.87, 0.0, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
        0.005,
    );
    let (s, c) = b.sin_cos();
    assert_rows(
        &Transform::rotation_x(b),
        [
            [1.0, 0.0, 0.0, 0.0],
            [0.0, c, -s, 0.0],
            [0.0, s, c, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
        1e-16,
    );
    assert_rows(
        &Transform::rotation_y(b),
        [
            [c, 0.0, s, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [-s, 0.0, c, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
        1e-16,
    );
}

#[test]
fn scale_matrix() {
    // Scale by 0.25 about the world origin.
    let m = Transform::scale(Point3::ORIGIN, 0.25);
    assert_rows(
        &m,
        [
            [0.25, 0.0, 0.0, 0.0],
            [0.0, 0.25, 0.0, 0.0],
            [0.0, 0.0, 0.25, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
        0.0,
    );
    // Non-uniform: P'.x = Sx P.x and so on.
    let m = Transform::scale_non_uniform(&Plane::WORLD_XY, 2.0, 3.0, 4.0);
    assert_eq!(
        m.transform_point(Point3::new(1.0, 1.0, 1.0)),
        Point3::new(2.0, 3.0, 4.0)
    );
}

#[test]
fn shear_matrices() {
    // Shear in x and y keeping z fixed: x' = x + a z, y' = y + b z.
    let (a, b) = (0.5, -2.0);
    let m = Transform::shear(
        &Plane::WORLD_XY,
        Vector3::X,
        Vector3::Y,
        Vector3::new(a, b, 1.0),
    );
    assert_rows(
        &m,
        [
            [1.0, 0.0, a, 0.0],
            [0.0, 1.0, b, 0.0],
            [0.0, 0.0, 1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
        0.0,
    );
    // Points with z = 0 do not move; z itself never changes.
    assert_eq!(
        m.transform_point(Point3::new(3.0, 4.0, 0.0)),
        Point3::new(3.0, 4.0, 0.0)
    );
    assert_eq!(
        m.transform_point(Point3::new(3.0, 4.0, 2.0)),
        Point3::new(4.0, 0.0, 2.0)
    );
}

#[test]
fn mirror_matrix() {
    // Mirror across the world XY plane: z changes sign and face directions flip.
    let m = Transform::mirror(&Plane::WORLD_XY);
    assert_rows(
        &m,
        [
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, -1.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
        0.0,
    );
    let (u, v) = (Vector3::X, Vector3::Y);
    let normal_before = u.cross(v);
    let normal_after = m.transform_vector(u).cross(m.transform_vector(v));
    assert_eq!(normal_after, normal_before);
    assert_eq!(m.transform_vector(normal_before), -normal_before);
    assert!(m.linear_determinant() < 0.0);
}

#[test]
fn planar_projection_matrices() {
    // P_xy = (x, y, 0), P_xz = (x, 0, z), P_yz = (0, y, z).
    let p = Point3::new(2.0, -3.0, 5.0);
    let xy = Transform::planar_projection(&Plane::WORLD_XY);
    assert_rows(
        &xy,
        [
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
        0.0,
    );
    assert_eq!(xy.transform_point(p), Point3::new(2.0, -3.0, 0.0));
    assert_eq!(
        Transform::planar_projection(&Plane::WORLD_ZX).transform_point(p),
        Point3::new(2.0, 0.0, 5.0)
    );
    assert_eq!(
        Transform::planar_projection(&Plane::WORLD_YZ).transform_point(p),
        Point3::new(0.0, -3.0, 5.0)
    );
    assert!(xy.inverse().is_err());
}

#[test]
fn combining_matrices_saves_operations() {
    // Method 1 (move, then rotate each point) equals method 2 (one combined matrix).
    let mv = Transform::translation(Vector3::new(1.0, 2.0, 3.0));
    let rot = Transform::rotation_z(0.7);
    let combined = rot * mv;
    for p in [
        Point3::new(1.0, 0.0, 0.0),
        Point3::new(-2.0, 4.0, 1.5),
        Point3::new(0.3, 0.3, -9.0),
    ] {
        let one_at_a_time = rot.transform_point(mv.transform_point(p));
        assert!(
            combined
                .transform_point(p)
                .abs_diff_eq(one_at_a_time, 1e-14)
        );
    }
}

#[test]
fn multiple_transformations_tutorial() {
    // Move the bounding box centre to the origin, rotate 45 degrees about z, scale by 0.2,
    // move back: matrix = m4 * m3 * m2 * m1 with m4 the inverse of m1.
    let geometry = [
        Point3::new(2.0, 3.0, 4.0),
        Point3::new(4.0, 5.0, 6.0),
        Point3::new(3.0, 3.5, 5.0),
    ];
    let center = BoundingBox::from_points(&geometry).unwrap().center();
    assert_eq!(center, Point3::new(3.0, 4.0, 5.0));
    let m1 = Transform::translation(Point3::ORIGIN - center);
    let m2 = Transform::rotation(PI / 4.0, Vector3::Z, Point3::ORIGIN).unwrap();
    let m3 = Transform::scale(Point3::ORIGIN, 0.2);
    let m4 = m1.inverse().unwrap();
    let matrix = m4 * m3 * m2 * m1;
    // The centre stays where it is; everything else shrinks towards it and turns.
    assert!(matrix.transform_point(center).abs_diff_eq(center, 1e-15));
    let k = 0.2 * (PI / 4.0).cos();
    assert_rows(
        &matrix,
        [
            [k, -k, 0.0, 3.0 - k * (3.0 - 4.0)],
            [k, k, 0.0, 4.0 - k * (3.0 + 4.0)],
            [0.0, 0.0, 0.2, 5.0 - 0.2 * 5.0],
            [0.0, 0.0, 0.0, 1.0],
        ],
        1e-15,
    );
    // Transforming each point by the four matrices in turn gives the same result.
    for p in geometry {
        let stepwise =
            m4.transform_point(m3.transform_point(m2.transform_point(m1.transform_point(p))));
        assert!(matrix.transform_point(p).abs_diff_eq(stepwise, 1e-14));
    }
}
