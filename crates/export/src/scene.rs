//! A scene: what a graph's outputs look like, as meshes, polylines and points, each item
//! remembering the output, tree path and index it came from.
//!
//! Every exporter (glTF, OBJ, STL, SVG, the picture and the viewer) reads a [`Scene`], so the
//! way values become drawable geometry is decided once, here.

use locus_kernel::{BoundingBox, Color, Mesh, Point3};
use locus_runtime::{DataTree, TreePath, Value, format_value};

use crate::tessellate::{self, Tessellation};

/// One item of an output, as drawable geometry.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneObject {
    /// The output's name.
    pub output: String,
    /// The branch path of the item.
    pub path: TreePath,
    /// The item's index in its branch.
    pub index: usize,
    /// The item as text (Grasshopper's panel notation), for labels and the viewer.
    pub label: String,
    /// Shaded surfaces, if the item has any.
    pub mesh: Option<Mesh>,
    /// Curves and edges as polylines (line strips).
    pub lines: Vec<Vec<Point3>>,
    /// Points.
    pub points: Vec<Point3>,
    /// The colour to draw the item in, when the item carries one.
    pub color: Option<Color>,
}

impl SceneObject {
    /// The bounding box of everything the object draws.
    pub fn bounding_box(&self) -> BoundingBox {
        let mut bbox = self
            .mesh
            .as_ref()
            .map_or(BoundingBox::EMPTY, Mesh::bounding_box);
        for &p in self.lines.iter().flatten().chain(&self.points) {
            bbox.include_point(p);
        }
        bbox
    }

    /// A name for the object: `output {0;1}[2]`.
    pub fn name(&self) -> String {
        format!("{} {}[{}]", self.output, self.path, self.index)
    }
}

/// Everything drawable in a set of outputs, in output, branch and item order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Scene {
    /// The objects.
    pub objects: Vec<SceneObject>,
    /// What could not be shown, as `output {path}[index]: reason` lines.
    pub skipped: Vec<String>,
}

impl Scene {
    /// An empty scene.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds every drawable item of a named output tree. Items with no geometry of their own
    /// (numbers, text, transforms, vectors) and nulls are passed over; geometry that cannot be
    /// tessellated is listed in [`Scene::skipped`].
    pub fn add_output(&mut self, output: &str, tree: &DataTree, settings: &Tessellation) {
        for (path, branch) in tree.branches() {
            for (index, value) in branch.values().enumerate() {
                let Some(value) = value else { continue };
                let mut object = SceneObject {
                    output: output.to_owned(),
                    path: path.clone(),
                    index,
                    label: format_value(&value),
                    mesh: None,
                    lines: Vec::new(),
                    points: Vec::new(),
                    color: None,
                };
                match fill(&mut object, &value, settings) {
                    Ok(true) => self.objects.push(object),
                    Ok(false) => {}
                    Err(reason) => self
                        .skipped
                        .push(format!("{} {path}[{index}]: {reason}", output)),
                }
            }
        }
    }

    /// The bounding box of the whole scene.
    pub fn bounding_box(&self) -> BoundingBox {
        self.objects
            .iter()
            .fold(BoundingBox::EMPTY, |b, o| b.union(&o.bounding_box()))
    }

    /// The number of triangles of all meshes.
    pub fn triangle_count(&self) -> usize {
        self.objects
            .iter()
            .filter_map(|o| o.mesh.as_ref())
            .map(Mesh::triangle_count)
            .sum()
    }
}

/// Fills `object` with the drawable form of `value`: `Ok(false)` for values with nothing to draw.
fn fill(object: &mut SceneObject, value: &Value, settings: &Tessellation) -> Result<bool, String> {
    match value {
        Value::Point(p) => object.points.push(*p),
        Value::Line(l) => object.lines.push(vec![l.from, l.to]),
        Value::Circle(c) => object
            .lines
            .push(tessellate::curve(&(*c).into(), settings)?),
        Value::Arc(a) => object
            .lines
            .push(tessellate::curve(&(*a).into(), settings)?),
        Value::Curve(c) => object.lines.push(tessellate::curve(c, settings)?),
        Value::Plane(p) => {
            // A plane is drawn as Grasshopper previews it: a small square grid is too much for
            // exports, so its origin and axes.
            object.points.push(p.origin);
            object
                .lines
                .push(vec![p.origin + p.x_axis, p.origin, p.origin + p.y_axis]);
        }
        Value::Surface(s) => object.mesh = Some(tessellate::surface(s, settings)?),
        Value::Mesh(m) => object.mesh = Some((**m).clone()),
        Value::Box(b) => {
            let brep = locus_kernel::Brep::from_box(b).map_err(|e| e.to_string())?;
            object.mesh = Some(tessellate::brep(&brep, settings)?);
            object
                .lines
                .extend(tessellate::brep_edges(&brep, settings)?);
        }
        Value::Brep(b) => {
            object.mesh = Some(tessellate::brep(b, settings)?);
            object.lines.extend(tessellate::brep_edges(b, settings)?);
        }
        _ => return Ok(false),
    }
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::*;
    use locus_kernel::{Circle, Interval, OrientedBox, Plane};

    #[test]
    fn outputs_become_objects_with_their_addresses() {
        let mut tree = DataTree::new();
        tree.branch_or_insert(TreePath::new(vec![0, 1]), locus_runtime::DataType::Generic);
        let mut points = DataTree::from_list(vec![Point3::ORIGIN, Point3::new(1.0, 2.0, 3.0)]);
        points
            .branch_or_insert(TreePath::new(vec![1]), locus_runtime::DataType::Point)
            .push_null();
        let mut scene = Scene::new();
        let settings = Tessellation::default();
        scene.add_output("P", &points, &settings);
        scene.add_output("empty", &tree, &settings);
        scene.add_output("numbers", &DataTree::from_list(vec![1.0, 2.0]), &settings);
        assert_eq!(scene.objects.len(), 2);
        assert_eq!(scene.objects[1].name(), "P {0}[1]");
        assert_eq!(scene.objects[1].points, [Point3::new(1.0, 2.0, 3.0)]);
        let bbox = scene.bounding_box();
        assert_eq!(
            (bbox.min, bbox.max),
            (Point3::ORIGIN, Point3::new(1.0, 2.0, 3.0))
        );
    }

    #[test]
    fn boxes_are_closed_meshes_with_edges() {
        let b = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
            Interval::new(0.0, 4.0),
        );
        let mut scene = Scene::new();
        scene.add_output("B", &DataTree::from_item(b), &Tessellation::default());
        let mesh = scene.objects[0].mesh.as_ref().unwrap();
        assert!(mesh.is_closed_and_oriented());
        assert!((mesh.volume() - 24.0).abs() < 1e-9);
        assert_eq!(scene.objects[0].lines.len(), 12);
    }

    #[test]
    fn circles_are_polylines_within_the_chord_tolerance() {
        let c = Circle {
            plane: Plane::WORLD_XY,
            radius: 10.0,
        };
        let mut scene = Scene::new();
        let mut settings = Tessellation::default();
        settings.parameters.max_chord_deviation = 0.01;
        scene.add_output("C", &DataTree::from_item(c), &settings);
        let line = &scene.objects[0].lines[0];
        assert_eq!(line.first(), line.last());
        for w in line.windows(2) {
            let mid = w[0] + (w[1] - w[0]) * 0.5;
            let sagitta = 10.0 - (mid - Point3::ORIGIN).length();
            assert!(sagitta <= 0.01 * 1.0001, "sagitta {sagitta}");
        }
    }
}
