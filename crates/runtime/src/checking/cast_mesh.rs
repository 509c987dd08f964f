//! Casts to and from meshes and colours: B-reps, surfaces and boxes become meshes through the
//! kernel's default meshing parameters (as Grasshopper's Mesh parameter meshes what it is given
//! with the document's default settings); meshes become boxes (their bounding box) and text;
//! colours come from `#RRGGBB` / `R,G,B` / `A,R,G,B` texts and ARGB integers.

use locus_kernel::{Brep, Color, Mesh, MeshingParameters, NurbsSurface, OrientedBox};

use crate::Shared;
use crate::file::literal_mesh::parse_hex_colour;

pub(crate) fn brep_to_mesh(brep: &Shared<Brep>) -> Option<Shared<Mesh>> {
    Mesh::from_brep(brep, &MeshingParameters::default())
        .ok()
        .map(Shared::new)
}

pub(crate) fn surface_to_mesh(surface: &Shared<NurbsSurface>) -> Option<Shared<Mesh>> {
    Mesh::from_surface(surface, &MeshingParameters::default())
        .ok()
        .map(Shared::new)
}

pub(crate) fn box_to_mesh(b: &OrientedBox) -> Option<Shared<Mesh>> {
    let brep = Brep::from_box(b).ok()?;
    Mesh::from_brep(&brep, &MeshingParameters::default())
        .ok()
        .map(Shared::new)
}

pub(crate) fn mesh_to_box(mesh: &Shared<Mesh>) -> Option<OrientedBox> {
    let b = mesh.bounding_box();
    if mesh.vertices().is_empty() {
        return None;
    }
    Some(OrientedBox::from_bounding_box(&b))
}

/// A colour from `#RRGGBB`, `#AARRGGBB`, `R,G,B` or `A,R,G,B` (channels 0 to 255).
pub(crate) fn text_to_colour(text: &str) -> Option<Color> {
    if let Some(c) = parse_hex_colour(text) {
        return Some(c);
    }
    let parts: Vec<u8> = text
        .split(',')
        .map(|p| p.trim().parse::<u8>().ok())
        .collect::<Option<_>>()?;
    match parts[..] {
        [r, g, b] => Some(Color::rgb(r, g, b)),
        [a, r, g, b] => Some(Color::rgba(r, g, b, a)),
        _ => None,
    }
}

/// A colour from a .NET ARGB integer (`Color.FromArgb(int)`), which must fit 32 bits.
pub(crate) fn integer_to_colour(i: &i64) -> Option<Color> {
    let bits = u32::try_from(*i)
        .ok()
        .or_else(|| i32::try_from(*i).ok().map(|x| x as u32))?;
    Some(Color::from_argb(bits))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{DataType, Value, cast_value};
    use locus_kernel::{Interval, Plane};

    #[test]
    fn boxes_and_breps_mesh_through_the_default_parameters() {
        let b = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
        );
        let Value::Mesh(m) = cast_value(&Value::Box(b), DataType::Mesh).unwrap() else {
            panic!("not a mesh")
        };
        assert!(m.is_closed_and_oriented());
        assert!((m.volume() - 6.0).abs() < 1e-12);
        let Value::Box(back) = cast_value(&Value::Mesh(m), DataType::Box).unwrap() else {
            panic!("not a box")
        };
        assert!((back.volume() - 6.0).abs() < 1e-12);
        assert!(cast_value(&Value::Brep(Shared::new(Brep::default())), DataType::Mesh).is_ok());
    }

    #[test]
    fn colours_read_from_text_and_integers() {
        assert_eq!(text_to_colour("#FF8000"), Some(Color::rgb(255, 128, 0)));
        assert_eq!(
            text_to_colour("#40FF8000"),
            Some(Color::rgba(255, 128, 0, 64))
        );
        assert_eq!(text_to_colour("255, 128, 0"), Some(Color::rgb(255, 128, 0)));
        assert_eq!(
            text_to_colour("64,255,128,0"),
            Some(Color::rgba(255, 128, 0, 64))
        );
        assert_eq!(text_to_colour("256,0,0"), None);
        assert_eq!(text_to_colour("red"), None);
        assert_eq!(integer_to_colour(&-16777216), Some(Color::BLACK));
        assert_eq!(integer_to_colour(&0xFFFF0000), Some(Color::rgb(255, 0, 0)));
        assert_eq!(integer_to_colour(&(1 << 40)), None);
        assert_eq!(
            cast_value(&Value::Colour(Color::rgb(1, 2, 3)), DataType::Text).unwrap(),
            Value::Text("1,2,3".into())
        );
    }
}
