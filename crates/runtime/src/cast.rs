//! Type casting between value types, modelled on Grasshopper's conversions.

use crate::DataType;

/// Whether items of type `from` can in general be cast to `to`, for checking wires before
/// running. Individual items may still fail (text that is not a number) and are then reported
/// per item at run time.
pub fn can_cast(from: DataType, to: DataType) -> bool {
    use DataType::*;
    if from == to || from == Generic || to == Generic {
        return true;
    }
    matches!(
        (from, to),
        (Number, Integer)
            | (Integer, Number)
            | (Number | Integer | Boolean, Text)
            | (Text, Number | Integer | Boolean | Point | Vector | Domain)
            | (Boolean, Integer | Number)
            | (Integer | Number, Boolean)
            | (Number | Integer, Domain)
            | (Point, Vector)
            | (Vector, Point)
            | (Point, Plane)
            | (Plane, Point)
            | (Domain, Number)
            | (Point | Vector | Plane | Domain | Transform, Text)
    )
}
