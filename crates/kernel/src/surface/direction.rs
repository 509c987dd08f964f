//! Parameter directions and sides of a surface's parameter rectangle.

/// One of the two parameter directions of a surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SurfaceDirection {
    /// The first parameter, `u`.
    U,
    /// The second parameter, `v`.
    V,
}

impl SurfaceDirection {
    /// The other direction.
    #[inline]
    pub fn other(self) -> Self {
        match self {
            Self::U => Self::V,
            Self::V => Self::U,
        }
    }

    /// The index of the direction: 0 for `u`, 1 for `v`.
    #[inline]
    pub fn index(self) -> usize {
        match self {
            Self::U => 0,
            Self::V => 1,
        }
    }
}

/// One of the four sides of a surface's parameter rectangle, named as openNURBS names them
/// (`ON_Surface::IsSingular` side indices 0 to 3).
///
/// With `u` pointing east and `v` pointing north: the south side is `v = v0`, east `u = u1`,
/// north `v = v1` and west `u = u0`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SurfaceSide {
    /// The side `v = v0` (openNURBS side 0).
    South,
    /// The side `u = u1` (openNURBS side 1).
    East,
    /// The side `v = v1` (openNURBS side 2).
    North,
    /// The side `u = u0` (openNURBS side 3).
    West,
}

impl SurfaceSide {
    /// The four sides in openNURBS order: south, east, north, west, which walks the parameter
    /// rectangle counter-clockwise starting at the corner `(u0, v0)`.
    pub const ALL: [Self; 4] = [Self::South, Self::East, Self::North, Self::West];

    /// The openNURBS side index, 0 to 3.
    #[inline]
    pub fn index(self) -> usize {
        match self {
            Self::South => 0,
            Self::East => 1,
            Self::North => 2,
            Self::West => 3,
        }
    }

    /// The direction in which the parameter is fixed along this side: `v` for south and north,
    /// `u` for east and west.
    #[inline]
    pub fn fixed_direction(self) -> SurfaceDirection {
        match self {
            Self::South | Self::North => SurfaceDirection::V,
            Self::East | Self::West => SurfaceDirection::U,
        }
    }

    /// Whether the fixed parameter is at the end (`u1` or `v1`) of its domain rather than the
    /// start.
    #[inline]
    pub fn is_at_end(self) -> bool {
        matches!(self, Self::East | Self::North)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sides_follow_opennurbs_numbering() {
        for (i, side) in SurfaceSide::ALL.into_iter().enumerate() {
            assert_eq!(side.index(), i);
        }
        assert_eq!(SurfaceSide::South.fixed_direction(), SurfaceDirection::V);
        assert_eq!(SurfaceSide::West.fixed_direction(), SurfaceDirection::U);
        assert!(SurfaceSide::North.is_at_end());
        assert!(!SurfaceSide::West.is_at_end());
        assert_eq!(SurfaceDirection::U.other(), SurfaceDirection::V);
    }
}
