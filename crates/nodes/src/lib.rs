//! The node library of locus: Grasshopper's components, by category.
//!
//! Node types are registered explicitly: `locus_nodes::register(&mut registry)` adds every
//! node type of the library, and each category module has its own `register`. Node ids are
//! `category.snake_name` (`maths.addition`), defined once as constants next to each node.
//!
//! # Index
//!
//! **Params** ([`params`])
//! - Primitive ([`params::primitive`]): Number \[Num\], Integer \[Int\], Boolean \[Bool\],
//!   Text \[Txt\], Domain.
//! - Geometry ([`params::geometry`]): Point \[Pt\], Vector \[Vec\], Plane \[Pln\].
//! - Curve ([`params::curve`]): Curve \[Crv\].
//! - Surface ([`params::surface`]): Surface \[Srf\].
//! - Box, B-rep, any geometry, transforms ([`params::brep`]): Box, Brep, Geometry \[Geo\]
//!   (Params › Geometry), Transform (Params › Primitive).
//! - Data, Relay, Line, Circle, Arc, Rectangle \[Rec\] ([`params::shapes`]); Graph Mapper
//!   \[Graph\] (Params › Input, [`params::graph_mapper`]); Data Dam \[Dam\] (Params › Util,
//!   [`params::dam`]).
//!
//! **Maths** ([`maths`])
//! - Operators ([`maths::operators`], [`maths::comparison`], [`maths::boolean`]): Addition
//!   \[A+B\], Subtraction \[A-B\], Multiplication \[A×B\], Division \[A/B\], Negative
//!   \[Neg\], Absolute \[Abs\], Power \[Pow\], Modulus \[Mod\], Larger Than \[Larger\],
//!   Smaller Than \[Smaller\], Equality \[Equals\], Gate And/Or/Xor/Nand/Nor/Xnor/Not.
//! - Domain ([`maths::domain`]): Construct Domain \[Dom\], Deconstruct Domain \[DeDomain\],
//!   Remap Numbers \[ReMap\].
//! - Script ([`maths::script`]): Expression, Evaluate \[Eval\]; the formula language is
//!   [`expression`].
//! - Lists and integers ([`maths::mass`]): Mass Addition \[MA\], Mass Multiplication \[MM\],
//!   Integer Division \[A\\B\]; Util and Trig ([`maths::util`]): Average \[Avr\], Maximum
//!   \[Max\], Minimum \[Min\], Round, Radians \[Rad\], Degrees \[Deg\], Bounds \[Bnd\]
//!   (Domain).
//!
//! **Sets** ([`sets`])
//! - List ([`sets::list`]): List Item \[Item\], List Length \[Lng\], Reverse List \[Rev\],
//!   Shift List \[Shift\], Sort List \[Sort\], Dispatch; ([`sets::list_split`]) Split List
//!   \[Split\], Partition List \[Partition\]; ([`sets::list_match`]) Longest List \[Long\],
//!   Shortest List \[Short\].
//! - Sequence ([`maths::sequence`], [`sets::sequence`]): Range, Series, Cull Pattern \[Cull\],
//!   Cull Index \[Cull i\], Cull Nth \[CullN\], Repeat Data \[Repeat\], Duplicate Data \[Dup\].
//! - Tree ([`sets::tree`], [`sets::streams`]): Graft Tree \[Graft\], Flatten Tree
//!   \[Flatten\], Simplify Tree \[Simplify\], Trim Tree \[Trim\], Prune Tree \[Prune\], Shift
//!   Paths \[PShift\], Flip Matrix \[Flip\], Path Mapper \[PathMapper\], Merge, Entwine,
//!   Explode Tree \[BANG!\], Tree Branch \[Branch\], Tree Item \[Item\], Tree Statistics
//!   \[TStat\].
//! - Editing ([`sets::list_edit`], [`sets::tree_edit`]): Sub List \[SubSet\], Insert Items
//!   \[Ins\], Replace Items \[Replace\], Pick'n'Choose \[P'n'C\], Weave, Sift Pattern \[Sift\],
//!   Cross Reference \[CrossRef\], Null Item \[Null\]; Stream Filter \[Filter\], Stream Gate
//!   \[Gate\], Clean Tree \[Clean\], Split Tree \[Split\], Match Tree \[Match\].
//! - Random ([`sets::random`]): Random, Jitter, Random Reduce \[Reduce\] (seeded with .NET's
//!   System.Random, [`sets::random::DotNetRandom`]), Fibonacci \[Fib\].
//! - Text ([`sets::text`]): Concatenate \[Concat\], Text Split \[Split\], Text Join \[Join\],
//!   Text Length \[Len\], Replace Text \[Rep\], Text Case \[Case\], Match Text \[TMatch\],
//!   Format.
//!
//! **Vector** ([`vector`])
//! - Point ([`vector::point`], [`vector::pull`]): Construct Point \[Pt\], Deconstruct
//!   \[pDecon\], Distance \[Dist\], Point Between \[PtBtw\], Pull Point \[Pull\].
//! - Vector ([`vector::vectors`], [`vector::products`]): Vector XYZ \[Vec\], Deconstruct Vector
//!   \[DeVec\], Unit X/Y/Z, Vector 2Pt \[Vec2Pt\], Unit Vector \[Unit\], Amplitude \[Amp\],
//!   Vector Length \[VLen\], Reverse \[Rev\], Rotate \[VRot\], Dot Product \[DProd\], Cross
//!   Product \[XProd\], Angle.
//! - Plane ([`vector::plane`]): Construct Plane \[Pl\], Plane 3Pt, Plane Normal \[Pl\], XY/YZ/XZ
//!   Plane, Deconstruct Plane \[DePlane\], Plane Coefficients \[PlEq\], Plane Closest Point.
//! - Grid, random points ([`vector::populate`]): Populate 2D \[Pop2D\], Populate 3D \[Pop3D\],
//!   Populate Geometry \[PopGeo\].
//!
//! **Transform** ([`transform`])
//! - Euclidean ([`transform::euclidean`]): Move, Rotate, Rotate Axis \[RotAx\], Rotate 3D
//!   \[Rot3D\], Mirror, Orient.
//! - Affine ([`transform::affine`]): Scale, Scale NU, Shear, Project \[Proj\], Orient Direction
//!   \[Orient\].
//! - Util ([`transform::util`]): Transform, Compound \[Comp\], Inverse Transform \[Inverse\],
//!   Deconstruct Transform \[DeXform\], Construct Transform \[Xform\]; all geometry goes
//!   through [`transform::apply::transform_value`].
//!
//! **Curve** ([`curve`])
//! - Primitive ([`curve::primitive`]): Line \[Ln\], Circle \[Cir\], Arc; ([`curve::primitive_more`])
//!   Line SDL, Circle CNR, Circle 3Pt, Circle Fit, Arc 3Pt, Arc SED, Polygon, Rectangle, and
//!   Curve Middle \[MidPt\] (Analysis).
//! - Spline ([`curve::spline`]): PolyLine \[PLine\], Bezier Span \[BzSpan\], Nurbs Curve
//!   \[Nurbs\], Nurbs Curve PWK \[NurbCrv\], Interpolate \[IntCrv\], Knot Vector \[Knots\].
//! - Analysis ([`curve::analysis`]): Control Points \[CP\], Evaluate Curve \[Eval\], Curvature,
//!   Curve Domain \[CrvDom\], End Points \[End\], Length \[Len\], Evaluate Length \[Eval\],
//!   Curve Closest Point \[Crv CP\], Curve Continuity \[Cont\]; Derivatives \[CDiv\]
//!   ([`curve::derivatives`], one output per derivative); Deconstruct Arc \[DArc\]
//!   ([`curve::deconstruct_arc`]); Point On Curve \[CurvePoint\] ([`curve::point_on_curve`],
//!   the position a setting, as in Grasshopper's object).
//! - Division ([`curve::division`]): Divide Curve \[Divide\], Divide Length \[DivLength\],
//!   Shatter; Dash Pattern \[Dash\] ([`curve::dash`]).
//! - Util ([`curve::util`]): Flip Curve \[Flip\], Split Curve \[Split\].
//! - The Curve parameter \[Crv\] is in [`params::curve`].
//!
//! **Surface** ([`surface`])
//! - Primitive ([`surface::primitive`]): Sphere \[Sph\], Sphere Fit \[SFit\], Cylinder \[Cyl\],
//!   Cone, Plane Surface \[PlaneSrf\].
//! - Freeform ([`surface::freeform`]): Surface From Points \[SrfGrid\]; ([`surface::lofting`])
//!   Ruled Surface \[RuleSrf\], Loft (normal, loose, tight, straight, uniform; closed; seams
//!   adjusted), Loft Options \[Loft Opt\], Revolution \[RevSrf\].
//! - Analysis ([`surface::analysis`]): Evaluate Surface \[EvalSrf\], Surface Closest Point
//!   \[Srf CP\], Principal Curvature \[Curvature\], Surface Curvature \[Curvature\].
//! - Util ([`surface::util`]): Divide Surface \[SDivide\], Iso Curve \[Iso\], Flip (surfaces).
//! - The Surface parameter \[Srf\] is in [`params::surface`].
//! - Boxes ([`surface::box_nodes`], [`surface::bounding_box`]): Box 2Pt \[Box\], Center Box \[Box\], Domain Box
//!   \[Box\], Box Rectangle \[BoxRec\], Bounding Box \[BBox\] (Primitive); Box Properties \[BoxProp\], Deconstruct
//!   Box \[DeBox\] (Analysis).
//! - B-reps ([`surface::brep`], [`surface::brep_analysis`]): Deconstruct Brep \[DeBrep\],
//!   Brep Edges \[Edges\], Area, Volume, Singular Points \[Sing\] (the book's singularity
//!   tutorial, not a stock Grasshopper component) (Analysis); Brep Join \[Join\] (Util).
//!
//! **Intersect** ([`intersect`])
//! - Mathematical ([`intersect::mathematical`]): Line | Line \[LLX\], Line | Plane \[PLX\],
//!   Plane | Plane \[PPX\], Plane | Plane | Plane \[3PX\], Curve | Plane \[PCX\],
//!   Curve | Line \[CLX\], within [`intersect::INTERSECTION_TOLERANCE`]; ([`intersect::mesh`])
//!   Mesh | Ray \[MeshRay\], Mesh | Plane \[Sec\].
//! - Physical ([`intersect::physical`]): Curve | Curve \[CCX\], Curve | Self \[CX\], Multiple
//!   Curves \[MCX\];
//!   ([`intersect::section`]) Brep | Brep \[BBX\].
//! - Shape ([`curve::regions`]): Region Union \[RUnion\], Region Intersection \[RInt\],
//!   Region Difference \[RDiff\] (booleans of planar regions, by the kernel's
//!   `Curve::region_boolean`); ([`intersect::shape`]) Solid Union \[SUnion\], Solid
//!   Difference \[SDiff\], Split Brep \[Split\] (the kernel's `Brep::boolean` and
//!   `Brep::split_by_brep`), and Point In Brep \[BrepInc\] (Surface › Analysis).
//!
//! **Script** ([`script`])
//! - Python Script \[Python\] (Grasshopper's GhPython, in Maths › Script there): a Python
//!   script per iteration, run in a separate Python process with the `locus` package.
//!
//! # Performance
//!
//! `cargo bench -p locus-nodes --bench library` measures the library's nodes against
//! hand-written loops at 1e3–1e6 items on one and two threads, with peak memory; the tables
//! (before and after issue 16's lifting work) are in `docs/performance.md`.
//!
//! Nodes with one item output whose inputs have concrete types and whose result is a plain
//! function of their items are declared with the runtime's `lift1`/`lift2`/`lift3`, which runs
//! them as one loop over the typed columns (the gates, the Vector › Point, Vector and Plane
//! item nodes, Inverse Transform, Line, Circle, Length, Sphere, Cylinder, Plane Surface). Nodes
//! with several outputs or per-item warnings use `lift1_with`/`lift2_with`/`lift3_with` (the
//! comparisons, Vector 2Pt, Vector XYZ, the Deconstruct nodes; Distance too, for the loop
//! without reports of `lift2_with_plain`), and Move and Rotate a typed
//! fast path for points (`fast_path2_with`/`fast_path3_with`). Nodes with settings, list
//! access or other Generic data keep the general solve function, called once per item
//! through `Solve`.
//!
//! `cargo bench -p locus-nodes --bench large_lists` runs one-node graphs of the library's
//! registry on a million items, next to hand-written loops over the same kernel calls in the
//! same run. Medians on the shared 2-core VM, load average 2.7–3.0 from other work during the
//! run, so the ratios to the hand loop of the same run are what counts:
//!
//! | case | time (median) | ratio to the hand loop |
//! | --- | --- | --- |
//! | hand loop: distance from 1M points to a point | 6.79 ms | 1 |
//! | Distance (lifted), one thread | 8.77 ms | 1.29× |
//! | Distance (lifted), two threads | 13.6 ms | 2.0× |
//! | Distance as a general solve function, one thread | 28.9 ms | 4.3× |
//! | hand loop: dot products of 1M vector pairs | 7.73 ms | 1 |
//! | Dot Product (lifted, three inputs), one thread | 9.41 ms | 1.22× |
//! | Dot Product (lifted), two threads | 9.05 ms | 1.17× |
//! | hand loop: larger than, 1M numbers against one | 1.14 ms | 1 |
//! | Larger Than (general: two outputs, a NaN warning), one thread | 35.2 ms | 31× |
//! | Larger Than, two threads | 31.9 ms | 28× |
//! | hand loop: add two lists of 1M numbers | 1.11 ms | 1 |
//! | Addition (Generic ports, number fast path), one thread | 1.78 ms | 1.78× (hand loop 1.00 ms, later run at load 0.6) |
//! | Addition (Generic ports, number fast path), two threads | 1.98 ms | 1.98× |
//! | Addition through the general solve function (before the fast path) | 237 ms | 214× |
//!
//! - Lifting made Distance 3.3× faster than the same checks and kernel call in a general solve
//!   function. The lifted loops cost 1.2–1.3× the hand loop here (the loop keeps a result per
//!   item and an error list; the runtime's own bench gets 1.0–1.15× for bare arithmetic).
//! - Two threads do not pay for these memory-bound loops: the runtime spreads a lifted loop
//!   only when its first chunk takes at least 8 ns an item, and Distance sits at about that
//!   threshold on this loaded machine, so it was spread and became slower (in a first run,
//!   under a load average of 3.6–3.9, it was 5.7 ms on two threads against 7.0 ms on one).
//! - Addition takes any operand (numbers, points, vectors, text) on Generic ports; through the
//!   general solve function every item costs an operand conversion, about 240 ns. Addition,
//!   Subtraction, Multiplication and Division therefore add a `fast_path2` for numbers: when
//!   both inputs arrive as Number columns (a Generic port keeps the column it is given) the
//!   runtime runs a typed loop, and any item whose inputs or result are not finite (which
//!   warns) sends the node back through the solve function, so results are always the general
//!   path's (`the_number_fast_path_gives_what_the_general_path_gives`). That made Addition of
//!   two 1M-number lists 130× faster (`cargo bench -p locus-nodes --bench large_lists --
//!   "Addition|add two"`).

mod constraints;
pub mod curve;
pub mod display;
pub mod expression;
pub mod intersect;
pub mod maths;
pub mod mesh;
pub mod params;
pub mod script;
pub mod sets;
pub mod surface;
#[cfg(test)]
mod test_support;
pub mod transform;
pub mod vector;

use locus_runtime::NodeRegistry;

/// Registers every node type of the library.
pub fn register(registry: &mut NodeRegistry) {
    params::register(registry);
    maths::register(registry);
    vector::register(registry);
    transform::register(registry);
    curve::register(registry);
    surface::register(registry);
    sets::register(registry);
    mesh::register(registry);
    display::register(registry);
    intersect::register(registry);
    script::register(registry);
}
