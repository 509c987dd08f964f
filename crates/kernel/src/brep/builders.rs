//! Constructors of B-reps: boxes, spheres, cylinders, cones, single surfaces and planar faces
//! bounded by polylines.

use crate::brep::{Brep, BrepEdge, BrepFace, BrepLoop, BrepTrim, BrepVertex, LoopKind, TrimKind};
use crate::curve::loop_plane::fit_plane;
use crate::surface::direction::{SurfaceDirection, SurfaceSide};
use crate::{
    Circle, Cone, Cylinder, Error, Interval, Line, NurbsCurve, NurbsSurface, OrientedBox, Plane,
    Point3, Result, Sphere, Vector3,
};

/// Assembles a B-rep part by part; [`Builder::finish`] links the topology.
#[derive(Debug, Default)]
pub(crate) struct Builder {
    pub(crate) brep: Brep,
}

impl Builder {
    pub(crate) fn vertex(&mut self, point: Point3) -> usize {
        self.brep.vertices.push(BrepVertex {
            point,
            edges: Vec::new(),
        });
        self.brep.vertices.len() - 1
    }

    pub(crate) fn edge(&mut self, curve: NurbsCurve, vertices: [usize; 2]) -> usize {
        self.brep.edges.push(BrepEdge {
            curve,
            vertices,
            trims: Vec::new(),
        });
        self.brep.edges.len() - 1
    }

    pub(crate) fn face(&mut self, surface: NurbsSurface, reversed: bool) -> usize {
        self.brep.faces.push(BrepFace {
            surface,
            loops: Vec::new(),
            reversed,
        });
        self.brep.faces.len() - 1
    }

    pub(crate) fn start_loop(&mut self, face: usize, kind: LoopKind) -> usize {
        self.brep.loops.push(BrepLoop {
            face,
            kind,
            trims: Vec::new(),
        });
        let index = self.brep.loops.len() - 1;
        self.brep.faces[face].loops.push(index);
        index
    }

    pub(crate) fn trim(
        &mut self,
        loop_index: usize,
        curve: NurbsCurve,
        edge: Option<usize>,
        reversed: bool,
        vertices: [usize; 2],
    ) {
        let index = self.brep.trims.len();
        self.brep.trims.push(BrepTrim {
            curve,
            edge,
            reversed,
            kind: TrimKind::Boundary,
            loop_index,
            vertices,
        });
        self.brep.loops[loop_index].trims.push(index);
    }

    pub(crate) fn finish(mut self) -> Brep {
        self.brep.link();
        self.brep
    }
}

/// A straight trim from `a` to `b` in parameter space.
fn line_trim(a: (f64, f64), b: (f64, f64)) -> Result<NurbsCurve> {
    Line::new(Point3::new(a.0, a.1, 0.0), Point3::new(b.0, b.1, 0.0)).to_nurbs()
}

/// A straight 3-D edge curve, with a clear error for coincident ends.
fn line_edge(a: Point3, b: Point3) -> Result<NurbsCurve> {
    if a.distance(b) <= crate::geometry::tolerance::ZERO_TOLERANCE * (1.0 + a.to_vector().length())
    {
        return Err(Error::ZeroLength { what: "brep edge" });
    }
    Line::new(a, b).to_nurbs()
}

/// The trim of the whole side of a surface's parameter rectangle, in the counter-clockwise
/// direction of the outer loop.
fn side_trim(surface: &NurbsSurface, side: SurfaceSide) -> Result<NurbsCurve> {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let (a, b) = match side {
        SurfaceSide::South => ((du.t0, dv.t0), (du.t1, dv.t0)),
        SurfaceSide::East => ((du.t1, dv.t0), (du.t1, dv.t1)),
        SurfaceSide::North => ((du.t1, dv.t1), (du.t0, dv.t1)),
        SurfaceSide::West => ((du.t0, dv.t1), (du.t0, dv.t0)),
    };
    line_trim(a, b)
}

impl Brep {
    /// The box with the eight given corners, as openNURBS's `ON_BrepBox` and Rhino's
    /// `Brep.CreateFromBox`: corners 0 to 3 are the bottom, counter-clockwise seen from the top,
    /// and corners 4 to 7 the top, each above the bottom corner with the same index minus 4.
    ///
    /// The result has 6 faces (front 0-1-5-4, right 1-2-6-5, back 2-3-7-6, left 3-0-4-7,
    /// bottom 0-3-2-1, top 4-5-6-7), 12 line edges (0-1, 1-2, 2-3, 3-0, 4-5, 5-6, 6-7, 7-4,
    /// 0-4, 1-5, 2-6, 3-7) and 8 vertices. Each face is the bilinear surface through its four
    /// corners (planar for a true box) with domains `[0, |ab|] × [0, |ad|]` along its first and
    /// last sides. If the corners are given in the mirrored order, the faces are marked
    /// reversed so that they still face outwards.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for non-finite corners, [`Error::ZeroLength`] if two corners that
    /// share an edge coincide.
    pub fn from_box_corners(corners: &[Point3; 8]) -> Result<Self> {
        if corners.iter().any(|p| !p.is_finite()) {
            return Err(Error::NotFinite { what: "box corner" });
        }
        const EDGES: [[usize; 2]; 12] = [
            [0, 1],
            [1, 2],
            [2, 3],
            [3, 0],
            [4, 5],
            [5, 6],
            [6, 7],
            [7, 4],
            [0, 4],
            [1, 5],
            [2, 6],
            [3, 7],
        ];
        const FACES: [[usize; 4]; 6] = [
            [0, 1, 5, 4],
            [1, 2, 6, 5],
            [2, 3, 7, 6],
            [3, 0, 4, 7],
            [0, 3, 2, 1],
            [4, 5, 6, 7],
        ];
        let mut b = Builder::default();
        for &p in corners {
            b.vertex(p);
        }
        for [s, e] in EDGES {
            b.edge(line_edge(corners[s], corners[e])?, [s, e]);
        }
        let find_edge = |s: usize, e: usize| -> (usize, bool) {
            let i = EDGES
                .iter()
                .position(|&pair| pair == [s, e] || pair == [e, s])
                .expect("every face side is a box edge");
            (i, EDGES[i] != [s, e])
        };
        for quad in FACES {
            let [pa, pb, pc, pd] = quad.map(|k| corners[k]);
            let (lu, lv) = (pa.distance(pb), pa.distance(pd));
            let surface = NurbsSurface::from_flat(
                [1, 1],
                [2, 2],
                vec![pa, pd, pb, pc],
                vec![1.0; 4],
                [vec![0.0, lu], vec![0.0, lv]],
            )?;
            let face = b.face(surface, false);
            let outer = b.start_loop(face, LoopKind::Outer);
            let uv = [(0.0, 0.0), (lu, 0.0), (lu, lv), (0.0, lv)];
            for k in 0..4 {
                let (s, e) = (quad[k], quad[(k + 1) % 4]);
                let (edge, reversed) = find_edge(s, e);
                b.trim(
                    outer,
                    line_trim(uv[k], uv[(k + 1) % 4])?,
                    Some(edge),
                    reversed,
                    [s, e],
                );
            }
        }
        let mut brep = b.finish();
        if brep.signed_volume_estimate() < 0.0 {
            for f in &mut brep.faces {
                f.reversed = true;
            }
        }
        Ok(brep)
    }

    /// The B-rep of an oriented box (Rhino's `Brep.CreateFromBox(Box)`, Grasshopper's box
    /// as a B-rep): [`from_box_corners`](Self::from_box_corners) on the box's corners, after
    /// making its intervals increasing.
    ///
    /// # Errors
    /// [`Error::NotFinite`] for a non-finite box, [`Error::ZeroLength`] for a flat box (an
    /// interval of zero length).
    pub fn from_box(oriented_box: &OrientedBox) -> Result<Self> {
        if !oriented_box.is_finite() {
            return Err(Error::NotFinite { what: "box" });
        }
        Self::from_box_corners(&oriented_box.made_increasing().corners())
    }

    /// One untrimmed face on a whole surface (Rhino's `Brep.CreateFromSurface`): the outer loop
    /// runs around the parameter rectangle; collapsed sides get singular trims, and sides that
    /// meet (a closed direction) share a seam edge.
    ///
    /// # Errors
    /// [`Error::NotFinite`] if an edge curve cannot be built (never for a valid surface).
    pub fn from_surface(surface: NurbsSurface) -> Result<Self> {
        let mut b = Builder::default();
        add_surface_face(&mut b, surface)?;
        Ok(b.finish())
    }

    /// The sphere as Rhino builds it: one face on the sphere's NURBS form, one seam edge from
    /// the south to the north pole, two vertices at the poles, and two singular trims.
    ///
    /// # Errors
    /// As [`Sphere::to_nurbs`].
    pub fn from_sphere(sphere: &Sphere) -> Result<Self> {
        Self::from_surface(sphere.to_nurbs()?)
    }

    /// The cylinder as a B-rep. With `capped`, a closed solid (Rhino's
    /// `Brep.CreateFromCylinder(cylinder, true, true)`, Grasshopper's Cylinder): the lateral
    /// face plus two planar caps trimmed by circles, 3 faces, 3 edges (the seam and the two
    /// circles) and 2 vertices on the seam. Without, the open tube: 1 face with the same
    /// edges, the circles naked.
    ///
    /// # Errors
    /// As [`Cylinder::to_nurbs`].
    pub fn from_cylinder(cylinder: &Cylinder, capped: bool) -> Result<Self> {
        let mut b = Builder::default();
        let sides = add_surface_face(&mut b, cylinder.to_nurbs()?)?;
        if capped {
            let axis = cylinder.plane.z_axis;
            // A cylinder too thin for its circles to be told from points has no edges to cap.
            let degenerate = Error::Degenerate { what: "cylinder" };
            let south = sides.south.ok_or(degenerate.clone())?;
            let north = sides.north.ok_or(degenerate)?;
            add_cap(
                &mut b,
                cylinder.circle_plane_at(cylinder.height.t0),
                cylinder.radius,
                -axis,
                south,
            )?;
            add_cap(
                &mut b,
                cylinder.circle_plane_at(cylinder.height.t1),
                cylinder.radius,
                axis,
                north,
            )?;
        }
        Ok(b.finish())
    }

    /// The cone as a B-rep: the lateral face with a singular trim at the apex, the seam edge
    /// from the apex to the base circle and the base circle edge, 2 vertices (apex and the
    /// seam's base point). With `capped`, a planar base trimmed by the circle closes it
    /// (Rhino's `Brep.CreateFromCone(cone, true)`).
    ///
    /// # Errors
    /// As [`Cone::to_nurbs`].
    pub fn from_cone(cone: &Cone, capped: bool) -> Result<Self> {
        let mut b = Builder::default();
        let sides = add_surface_face(&mut b, cone.to_nurbs()?)?;
        if capped {
            let away = cone.plane.z_axis * cone.height.signum();
            let base_edge = match (sides.south, sides.north) {
                (Some(e), None) | (None, Some(e)) => e,
                _ => return Err(Error::Degenerate { what: "cone" }),
            };
            add_cap(&mut b, cone.base_plane(), cone.radius, away, base_edge)?;
        }
        Ok(b.finish())
    }

    /// A planar face bounded by a closed polyline (Grasshopper's Boundary Surfaces on a
    /// polyline): the plane is fitted through the points (Newell's normal, origin at the first
    /// point, x axis along the first segment), the surface is the plane rectangle around the
    /// polygon, and the outer loop has one line trim and one line edge per segment. The
    /// vertices are the points projected onto the plane.
    ///
    /// The closing segment is implied: the last point may repeat the first or not.
    ///
    /// # Errors
    /// [`Error::TooFewPoints`] for fewer than 3 distinct points, [`Error::Collinear`] when they
    /// span no plane, [`Error::InvalidInput`] when a point lies farther than `tolerance` from
    /// the plane or the polygon crosses itself, [`Error::NotFinite`] for NaN.
    pub fn from_planar_polyline(points: &[Point3], tolerance: f64) -> Result<Self> {
        Self::from_planar_polylines(points, &[], tolerance)
    }

    /// A planar face bounded by the closed polyline `outer` with holes bounded by the closed
    /// polylines `holes`, which must lie in the same plane, inside the outer polygon and
    /// apart from it and from each other. Inner loops run clockwise whatever the holes'
    /// direction.
    ///
    /// # Errors
    /// As [`Brep::from_planar_polyline`], and [`Error::InvalidInput`] for a hole outside the
    /// outer polygon or crossing a boundary.
    pub fn from_planar_polylines(
        outer: &[Point3],
        holes: &[Vec<Point3>],
        tolerance: f64,
    ) -> Result<Self> {
        if !tolerance.is_finite() || tolerance < 0.0 {
            return Err(Error::InvalidInput(format!(
                "tolerance must be finite and not negative, got {tolerance}"
            )));
        }
        let outer = clean_polygon(outer)?;
        let plane = fit_plane(&outer)?;
        let to_uv = |polygon: &[Point3]| -> Result<Vec<(f64, f64)>> {
            polygon
                .iter()
                .map(|&p| {
                    let [u, v, w] = plane.local_coordinates(p);
                    if w.abs() > tolerance {
                        Err(Error::InvalidInput(format!(
                            "point ({}, {}, {}) lies {} from the plane of the polyline, more \
                             than the tolerance {tolerance}",
                            p.x,
                            p.y,
                            p.z,
                            w.abs()
                        )))
                    } else {
                        Ok((u, v))
                    }
                })
                .collect()
        };
        let outer_uv = to_uv(&outer)?;
        if signed_area(&outer_uv) <= 0.0 {
            return Err(Error::Collinear);
        }
        let mut loops_uv = vec![outer_uv];
        for hole in holes {
            let mut uv = to_uv(&clean_polygon(hole)?)?;
            if signed_area(&uv) > 0.0 {
                uv.reverse();
            }
            if !point_in_polygon(uv[0], &loops_uv[0]) {
                return Err(Error::InvalidInput(
                    "a hole lies outside the outer polyline".into(),
                ));
            }
            loops_uv.push(uv);
        }
        check_no_crossings(&loops_uv)?;

        let (mut u0, mut u1, mut v0, mut v1) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for &(u, v) in &loops_uv[0] {
            u0 = u0.min(u);
            u1 = u1.max(u);
            v0 = v0.min(v);
            v1 = v1.max(v);
        }
        let surface =
            NurbsSurface::from_plane(&plane, Interval::new(u0, u1), Interval::new(v0, v1))?;
        let mut b = Builder::default();
        let face = b.face(surface, false);
        for (k, uv) in loops_uv.iter().enumerate() {
            let kind = if k == 0 {
                LoopKind::Outer
            } else {
                LoopKind::Inner
            };
            let l = b.start_loop(face, kind);
            let first_vertex = b.brep.vertices.len();
            for &(u, v) in uv {
                b.vertex(plane.point_at(u, v, 0.0));
            }
            let n = uv.len();
            for i in 0..n {
                let (s, e) = (first_vertex + i, first_vertex + (i + 1) % n);
                let edge = b.edge(
                    line_edge(b.brep.vertices[s].point, b.brep.vertices[e].point)?,
                    [s, e],
                );
                b.trim(
                    l,
                    line_trim(uv[i], uv[(i + 1) % n])?,
                    Some(edge),
                    false,
                    [s, e],
                );
            }
        }
        Ok(b.finish())
    }

    /// A rough signed volume from the faces' corner points, used only to tell whether a box's
    /// corners were given in the mirrored order.
    fn signed_volume_estimate(&self) -> f64 {
        let mut volume = 0.0;
        for f in &self.faces {
            let s = &f.surface;
            let (du, dv) = (s.domain_u(), s.domain_v());
            let a = s.point_at(du.t0, dv.t0).to_vector();
            let b = s.point_at(du.t1, dv.t0).to_vector();
            let c = s.point_at(du.t1, dv.t1).to_vector();
            let d = s.point_at(du.t0, dv.t1).to_vector();
            volume += a.dot(b.cross(c)) + a.dot(c.cross(d));
        }
        volume
    }
}

/// The edges made for the south and north sides of a face added by [`add_surface_face`]
/// (`None` where the side is singular).
#[derive(Debug)]
struct SurfaceSides {
    south: Option<usize>,
    north: Option<usize>,
}

/// Adds one face on a whole surface with its outer loop around the parameter rectangle.
///
/// The loop's trims run counter-clockwise along the south (`v = v0`), east, north and west
/// sides. A collapsed side gets a singular trim at its collapse point. In a closed direction
/// the two opposite sides share one seam edge, the isocurve of the side met first (south or
/// east), which coincides with its opposite; other sides get their own isocurve edges. Every edge runs in the direction of increasing
/// parameter, so the north and west trims run against their edges. Corners that coincide by
/// construction (across a collapsed side or a seam) share one vertex.
fn add_surface_face(b: &mut Builder, surface: NurbsSurface) -> Result<SurfaceSides> {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let scale = surface
        .points()
        .iter()
        .fold(0.0f64, |m, p| m.max(p.to_vector().length()));
    let closed_u = surface.is_closed(SurfaceDirection::U, 1e-12 * (1.0 + scale));
    let closed_v = surface.is_closed(SurfaceDirection::V, 1e-12 * (1.0 + scale));
    let singular = SurfaceSide::ALL.map(|s| surface.is_singular(s));

    // Corners counter-clockwise from (u0, v0); side k runs from corner k to corner k + 1.
    let corner_uv = [
        (du.t0, dv.t0),
        (du.t1, dv.t0),
        (du.t1, dv.t1),
        (du.t0, dv.t1),
    ];
    let mut class = [0usize, 1, 2, 3];
    fn root(class: &[usize; 4], mut k: usize) -> usize {
        while class[k] != k {
            k = class[k];
        }
        k
    }
    let mut join = |a: usize, b: usize| {
        let (ra, rb) = (root(&class, a), root(&class, b));
        class[ra.max(rb)] = ra.min(rb);
    };
    for (k, &collapsed) in singular.iter().enumerate() {
        if collapsed {
            join(k, (k + 1) % 4);
        }
    }
    if closed_u {
        join(0, 1);
        join(3, 2);
    }
    if closed_v {
        join(0, 3);
        join(1, 2);
    }
    let mut vertex_of_root = [usize::MAX; 4];
    let mut corner = [0usize; 4];
    for (k, c) in corner.iter_mut().enumerate() {
        let r = root(&class, k);
        if vertex_of_root[r] == usize::MAX {
            let (u, v) = corner_uv[r];
            vertex_of_root[r] = b.vertex(surface.point_at(u, v));
        }
        *c = vertex_of_root[r];
    }

    let iso = |side: SurfaceSide| -> Result<NurbsCurve> {
        match side {
            SurfaceSide::South => surface.isocurve(SurfaceDirection::U, dv.t0),
            SurfaceSide::North => surface.isocurve(SurfaceDirection::U, dv.t1),
            SurfaceSide::West => surface.isocurve(SurfaceDirection::V, du.t0),
            SurfaceSide::East => surface.isocurve(SurfaceDirection::V, du.t1),
        }
    };
    // Each edge's curve and vertices in the direction of increasing parameter.
    let edge_ends = |side: SurfaceSide| match side {
        SurfaceSide::South => [corner[0], corner[1]],
        SurfaceSide::East => [corner[1], corner[2]],
        SurfaceSide::North => [corner[3], corner[2]],
        SurfaceSide::West => [corner[0], corner[3]],
    };
    let mut edge_of: [Option<usize>; 4] = [None; 4];
    for (k, side) in SurfaceSide::ALL.into_iter().enumerate() {
        if singular[k] || edge_of[k].is_some() {
            continue;
        }
        let e = b.edge(iso(side)?, edge_ends(side));
        edge_of[k] = Some(e);
        match side {
            SurfaceSide::South if closed_v => edge_of[2] = Some(e),
            SurfaceSide::East if closed_u => edge_of[3] = Some(e),
            _ => {}
        }
    }
    let face = b.face(surface.clone(), false);
    let outer = b.start_loop(face, LoopKind::Outer);
    for (k, side) in SurfaceSide::ALL.into_iter().enumerate() {
        let reversed = matches!(side, SurfaceSide::North | SurfaceSide::West);
        let ends = [corner[k], corner[(k + 1) % 4]];
        b.trim(
            outer,
            side_trim(&surface, side)?,
            edge_of[k],
            reversed,
            ends,
        );
    }
    Ok(SurfaceSides {
        south: edge_of[0],
        north: edge_of[2],
    })
}

/// Adds a planar cap: the disc of `radius` in `plane` (centred at its origin), facing
/// `outward`, trimmed by a circle along the existing closed edge `edge` (which runs
/// counter-clockwise about `plane.z_axis`, starting on `plane.x_axis`).
fn add_cap(
    b: &mut Builder,
    plane: Plane,
    radius: f64,
    outward: Vector3,
    edge: usize,
) -> Result<()> {
    // Facing along the circle's axis the cap keeps the plane's axes and its trim follows the
    // edge; facing against it the y axis flips, the circle turns clockwise in the cap's
    // parameters, and the counter-clockwise trim runs against the edge.
    let along = outward.dot(plane.z_axis) > 0.0;
    let cap_plane = if along {
        plane
    } else {
        Plane {
            origin: plane.origin,
            x_axis: plane.x_axis,
            y_axis: -plane.y_axis,
            z_axis: -plane.z_axis,
        }
    };
    let extent = Interval::new(-radius, radius);
    let surface = NurbsSurface::from_plane(&cap_plane, extent, extent)?;
    let face = b.face(surface, false);
    let l = b.start_loop(face, LoopKind::Outer);
    let trim = Circle::new(Plane::WORLD_XY, radius)?.to_nurbs();
    let vertex = b.brep.edges[edge].vertices[0];
    b.trim(l, trim, Some(edge), !along, [vertex, vertex]);
    Ok(())
}

/// The polygon's points without consecutive duplicates and without a repeated closing point.
fn clean_polygon(points: &[Point3]) -> Result<Vec<Point3>> {
    if points.iter().any(|p| !p.is_finite()) {
        return Err(Error::NotFinite {
            what: "polyline point",
        });
    }
    let scale = points
        .iter()
        .fold(0.0f64, |m, p| m.max(p.to_vector().length()));
    let same = |a: Point3, b: Point3| {
        a.distance(b) <= crate::geometry::tolerance::ZERO_TOLERANCE * (1.0 + scale)
    };
    let mut out: Vec<Point3> = Vec::with_capacity(points.len());
    for &p in points {
        if out.last().is_none_or(|&q| !same(p, q)) {
            out.push(p);
        }
    }
    while out.len() > 1 && same(out[0], out[out.len() - 1]) {
        out.pop();
    }
    if out.len() < 3 {
        return Err(Error::TooFewPoints {
            what: "a planar polyline face",
            needed: 3,
            got: out.len(),
        });
    }
    Ok(out)
}

/// The signed area of a polygon in the plane (positive when counter-clockwise).
pub(crate) fn signed_area(polygon: &[(f64, f64)]) -> f64 {
    let n = polygon.len();
    let (u0, v0) = polygon[0];
    let mut twice = 0.0;
    for i in 0..n {
        let (a, b) = (polygon[i], polygon[(i + 1) % n]);
        twice += (a.0 - u0) * (b.1 - v0) - (b.0 - u0) * (a.1 - v0);
    }
    0.5 * twice
}

/// Whether `p` lies inside the polygon (even-odd rule).
pub(crate) fn point_in_polygon(p: (f64, f64), polygon: &[(f64, f64)]) -> bool {
    let n = polygon.len();
    let mut inside = false;
    for i in 0..n {
        let (a, b) = (polygon[i], polygon[(i + 1) % n]);
        if (a.1 > p.1) != (b.1 > p.1) {
            let x = a.0 + (p.1 - a.1) / (b.1 - a.1) * (b.0 - a.0);
            if p.0 < x {
                inside = !inside;
            }
        }
    }
    inside
}

/// Rejects polygons that cross themselves or each other (segments that intersect other than
/// at the shared vertex of neighbours).
pub(crate) fn check_no_crossings(loops: &[Vec<(f64, f64)>]) -> Result<()> {
    // (start, end, loop, index within the loop)
    type Segment = ((f64, f64), (f64, f64), usize, usize);
    let segments: Vec<Segment> = loops
        .iter()
        .enumerate()
        .flat_map(|(l, poly)| {
            let n = poly.len();
            (0..n).map(move |i| (poly[i], poly[(i + 1) % n], l, i))
        })
        .collect();
    for (x, &(a, b, la, ia)) in segments.iter().enumerate() {
        for &(c, d, lc, ic) in &segments[x + 1..] {
            let n = loops[la].len();
            let neighbours = la == lc && ((ia + 1) % n == ic || (ic + 1) % n == ia);
            if segments_touch(a, b, c, d, neighbours) {
                return Err(Error::InvalidInput(if la == lc {
                    "the polyline crosses itself".into()
                } else {
                    "a hole touches or crosses another boundary".into()
                }));
            }
        }
    }
    Ok(())
}

/// Whether segments `ab` and `cd` share a point; for neighbouring segments their common
/// vertex does not count, only an overlap.
fn segments_touch(
    a: (f64, f64),
    b: (f64, f64),
    c: (f64, f64),
    d: (f64, f64),
    neighbours: bool,
) -> bool {
    let cross = |o: (f64, f64), p: (f64, f64), q: (f64, f64)| {
        (p.0 - o.0) * (q.1 - o.1) - (p.1 - o.1) * (q.0 - o.0)
    };
    let d1 = cross(c, d, a);
    let d2 = cross(c, d, b);
    let d3 = cross(a, b, c);
    let d4 = cross(a, b, d);
    if neighbours {
        // Neighbours share one vertex; they are bad only if collinear and folding back.
        if d1 == 0.0 && d2 == 0.0 {
            let dir = (b.0 - a.0, b.1 - a.1);
            let other = (d.0 - c.0, d.1 - c.1);
            return dir.0 * other.0 + dir.1 * other.1 < 0.0;
        }
        return false;
    }
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0))
        && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))
    {
        return true;
    }
    let on = |p: (f64, f64), q: (f64, f64), r: (f64, f64)| {
        r.0 >= p.0.min(q.0) && r.0 <= p.0.max(q.0) && r.1 >= p.1.min(q.1) && r.1 <= p.1.max(q.1)
    };
    (d1 == 0.0 && on(c, d, a))
        || (d2 == 0.0 && on(c, d, b))
        || (d3 == 0.0 && on(a, b, c))
        || (d4 == 0.0 && on(a, b, d))
}

#[cfg(test)]
mod tests;
