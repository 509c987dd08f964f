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
//!
//! **Transform** ([`transform`])
//! - Euclidean ([`transform::euclidean`]): Move, Rotate, Rotate Axis \[RotAx\], Rotate 3D
//!   \[Rot3D\], Mirror, Orient.
//! - Affine ([`transform::affine`]): Scale, Scale NU, Shear, Project \[Proj\].
//! - Util ([`transform::util`]): Transform, Compound \[Comp\], Inverse Transform \[Inverse\],
//!   Deconstruct Transform \[DeXform\], Construct Transform \[Xform\]; all geometry goes
//!   through [`transform::apply::transform_value`].
//!
//! **Curve** ([`curve`])
//! - Primitive ([`curve::primitive`]): Line \[Ln\], Circle \[Cir\], Arc.
//! - Spline ([`curve::spline`]): PolyLine \[PLine\], Bezier Span \[BzSpan\], Nurbs Curve
//!   \[Nurbs\], Nurbs Curve PWK \[NurbCrv\], Interpolate \[IntCrv\], Knot Vector \[Knots\].
//! - Analysis ([`curve::analysis`]): Control Points \[CP\], Evaluate Curve \[Eval\], Curvature,
//!   Curve Domain \[CrvDom\], End Points \[End\], Length \[Len\], Evaluate Length \[Eval\],
//!   Curve Closest Point \[Crv CP\], Curve Continuity \[Cont\].
//! - Division ([`curve::division`]): Divide Curve \[Divide\], Divide Length \[DivLength\],
//!   Shatter.
//! - Util ([`curve::util`]): Flip Curve \[Flip\], Split Curve \[Split\].
//! - The Curve parameter \[Crv\] is in [`params::curve`].
//!
//! **Surface** ([`surface`])
//! - Primitive ([`surface::primitive`]): Sphere \[Sph\], Cylinder \[Cyl\], Cone, Plane Surface
//!   \[PlaneSrf\].
//! - Freeform ([`surface::freeform`]): Surface From Points \[SrfGrid\].
//! - Analysis ([`surface::analysis`]): Evaluate Surface \[EvalSrf\], Surface Closest Point
//!   \[Srf CP\], Principal Curvature \[Curvature\], Surface Curvature \[Curvature\].
//! - Util ([`surface::util`]): Divide Surface \[SDivide\], Iso Curve \[Iso\].
//! - The Surface parameter \[Srf\] is in [`params::surface`].
//! - Boxes ([`surface::box_nodes`], [`surface::bounding_box`]): Box 2Pt \[Box\], Center Box \[Box\], Domain Box
//!   \[Box\], Bounding Box \[BBox\] (Primitive); Box Properties \[BoxProp\], Deconstruct
//!   Box \[DeBox\] (Analysis).
//! - B-reps ([`surface::brep`], [`surface::brep_analysis`]): Deconstruct Brep \[DeBrep\],
//!   Brep Edges \[Edges\], Area, Volume, Singular Points \[Sing\] (the book's singularity
//!   tutorial, not a stock Grasshopper component) (Analysis); Brep Join \[Join\] (Util).

pub mod curve;
pub mod expression;
pub mod maths;
pub mod params;
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
}
