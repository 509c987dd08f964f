//! Wavefront OBJ export: one `o` group per item (named `output {path}[index]`), meshes as
//! faces (quads stay quads), curves as `l` polylines, points as `p`. Coordinates are written
//! Z-up as they are (OBJ has no up axis; Rhino reads them as written).

use std::fmt::Write as _;

use crate::scene::Scene;

/// The scene as OBJ text.
pub fn to_obj(scene: &Scene) -> String {
    let mut out = String::from("# written by locus\n");
    let mut base = 1usize;
    let mut normal_base = 1usize;
    for object in &scene.objects {
        let _ = writeln!(out, "o {}", object.name().replace(char::is_whitespace, "_"));
        if let Some(mesh) = &object.mesh {
            for p in mesh.vertices() {
                let _ = writeln!(out, "v {} {} {}", p.x, p.y, p.z);
            }
            let normals = mesh.normals();
            if let Some(normals) = normals {
                for n in normals {
                    let _ = writeln!(out, "vn {} {} {}", n.x, n.y, n.z);
                }
            }
            for face in mesh.faces() {
                out.push('f');
                for &v in face.corners() {
                    let (v, n) = (v as usize + base, v as usize + normal_base);
                    if normals.is_some() {
                        let _ = write!(out, " {v}//{n}");
                    } else {
                        let _ = write!(out, " {v}");
                    }
                }
                out.push('\n');
            }
            base += mesh.vertices().len();
            if normals.is_some() {
                normal_base += mesh.vertices().len();
            }
        }
        for line in &object.lines {
            for p in line {
                let _ = writeln!(out, "v {} {} {}", p.x, p.y, p.z);
            }
            out.push('l');
            for k in 0..line.len() {
                let _ = write!(out, " {}", base + k);
            }
            out.push('\n');
            base += line.len();
        }
        for p in &object.points {
            let _ = writeln!(out, "v {} {} {}\np {base}", p.x, p.y, p.z);
            base += 1;
        }
    }
    out
}
