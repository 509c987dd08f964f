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
//! **Sets**
//! - Sequence ([`maths::sequence`]): Range, Series.
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
