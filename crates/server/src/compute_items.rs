//! Rhino.Compute's items: `{"type": ".NET type name", "data": "JSON text"}` read into locus
//! values against an input's type, and locus values written the way Compute writes them.
//!
//! Reading accepts the forms real clients send (see `docs/server.md`): `data` as a JSON string
//! or as bare JSON, items without `type` (the input's type decides), booleans as `"True"`, keys
//! of geometry structs in any case. Geometry is validated by the kernel's constructors.

use locus_kernel::{
    Arc, Circle, Interval, Line, OrientedBox, Plane, Point3, Transform, UvInterval, Vector3,
};
use locus_runtime::{DataType, Value, cast_value};
use serde_json::{Map, Value as Json, json};

use crate::archive;

/// The .NET type name of a value type in Compute's answers (`None`: archive geometry).
pub fn dotnet_type(data_type: DataType) -> Option<&'static str> {
    Some(match data_type {
        DataType::Number => "System.Double",
        DataType::Integer => "System.Int32",
        DataType::Boolean => "System.Boolean",
        DataType::Text => "System.String",
        DataType::Point => "Rhino.Geometry.Point3d",
        DataType::Vector => "Rhino.Geometry.Vector3d",
        DataType::Plane => "Rhino.Geometry.Plane",
        DataType::Domain => "Rhino.Geometry.Interval",
        // Inferred: RhinoCommon's struct for Grasshopper's Domain², its U and V intervals.
        DataType::Domain2 => "Rhino.Geometry.UVInterval",
        DataType::Transform => "Rhino.Geometry.Transform",
        DataType::Box => "Rhino.Geometry.Box",
        DataType::Line => "Rhino.Geometry.Line",
        DataType::Circle => "Rhino.Geometry.Circle",
        DataType::Arc => "Rhino.Geometry.Arc",
        DataType::Colour => "System.Drawing.Color",
        DataType::Curve
        | DataType::Surface
        | DataType::Brep
        | DataType::Mesh
        | DataType::Generic => return None,
    })
}

/// The locus type a .NET type name stands for; `Err` for archive types, `None` if unknown.
fn type_of_dotnet(name: &str) -> Option<Result<DataType, ()>> {
    let name = name.split(',').next().unwrap_or(name).trim();
    Some(Ok(match name {
        "System.Double" | "System.Single" | "System.Decimal" => DataType::Number,
        "System.Int32" | "System.Int64" | "System.Int16" => DataType::Integer,
        "System.Boolean" => DataType::Boolean,
        "System.String" => DataType::Text,
        "Rhino.Geometry.Point3d" | "Rhino.Geometry.Point3f" => DataType::Point,
        "Rhino.Geometry.Vector3d" | "Rhino.Geometry.Vector3f" => DataType::Vector,
        "Rhino.Geometry.Plane" => DataType::Plane,
        "Rhino.Geometry.Interval" => DataType::Domain,
        "Rhino.Geometry.UVInterval" => DataType::Domain2,
        "Rhino.Geometry.Transform" => DataType::Transform,
        "Rhino.Geometry.Box" => DataType::Box,
        "Rhino.Geometry.Line" => DataType::Line,
        "Rhino.Geometry.Circle" => DataType::Circle,
        "Rhino.Geometry.Arc" => DataType::Arc,
        _ if archive::ARCHIVE_TYPES.contains(&name) => return Some(Err(())),
        _ => return None,
    }))
}

/// Reads one Compute item for an input of type `target`; `Ok(None)` is a null item.
///
/// # Errors
/// The reason, in plain words, when the item is not a value of a type that casts to `target`.
pub fn decode_item(item: &Json, target: DataType) -> Result<Option<Value>, String> {
    let obj = match item {
        Json::Null => return Ok(None),
        Json::Object(obj) => obj,
        other => {
            return Err(format!(
                "an item must be an object {{\"type\", \"data\"}}, not {}",
                kind_of(other)
            ));
        }
    };
    let type_name = match obj.get("type") {
        None | Some(Json::Null) => None,
        Some(Json::String(s)) => Some(s.as_str()),
        Some(other) => return Err(format!("\"type\" must be a string, not {}", kind_of(other))),
    };
    let data = match obj.get("data") {
        None | Some(Json::Null) => return Ok(None),
        Some(d) => d,
    };
    let sent = match type_name {
        Some(name) => match type_of_dotnet(name) {
            Some(Ok(t)) => t,
            Some(Err(())) => return archive::decode(name, &parse_data(data)?).map(Some),
            None => return Err(format!("unknown item type \"{name}\"")),
        },
        None => target,
    };
    let value = if sent == DataType::Text {
        Value::Text(text_of(data))
    } else if sent == DataType::Generic {
        infer(&parse_data(data)?)?
    } else {
        value_of(&parse_data(data)?, sent)?
    };
    if target == DataType::Generic || value.data_type() == target {
        return Ok(Some(value));
    }
    cast_value(&value, target).map(Some).map_err(|e| {
        format!(
            "a {} item cannot be used as a {}: {e}",
            value.data_type().name(),
            target.name()
        )
    })
}

/// The JSON inside `data`: a string holding JSON is parsed (Python's `"True"`/`"False"` are
/// booleans), anything else is taken as it is.
fn parse_data(data: &Json) -> Result<Json, String> {
    match data {
        Json::String(s) => match serde_json::from_str::<Json>(s) {
            Ok(j) => Ok(j),
            Err(e) => match s.trim() {
                "True" => Ok(Json::Bool(true)),
                "False" => Ok(Json::Bool(false)),
                // Json.NET writes `NaN` and `Infinity` bare: numbers, refused later as such.
                t if t.parse::<f64>().is_ok() => Ok(Json::String(t.to_owned())),
                _ => Err(format!("\"data\" is not JSON: {e}")),
            },
        },
        other => Ok(other.clone()),
    }
}

/// A text item: Compute writes strings as JSON strings (`"\"abc\""`); bare text is taken too.
fn text_of(data: &Json) -> String {
    match data {
        Json::String(s) => match serde_json::from_str::<Json>(s) {
            Ok(Json::String(inner)) => inner,
            _ => s.clone(),
        },
        other => other.to_string(),
    }
}

fn kind_of(j: &Json) -> &'static str {
    match j {
        Json::Null => "null",
        Json::Bool(_) => "a boolean",
        Json::Number(_) => "a number",
        Json::String(_) => "a string",
        Json::Array(_) => "an array",
        Json::Object(_) => "an object",
    }
}

/// A value of an item sent without `type` to an input that takes anything.
fn infer(j: &Json) -> Result<Value, String> {
    match j {
        Json::Bool(b) => Ok(Value::Boolean(*b)),
        Json::Number(n) if n.is_i64() => Ok(Value::Integer(n.as_i64().unwrap_or_default())),
        Json::Number(_) => value_of(j, DataType::Number),
        Json::String(s) => Ok(Value::Text(s.clone())),
        Json::Object(o) if field(o, "X").is_some() => value_of(j, DataType::Point),
        other => Err(format!(
            "cannot tell the type of {} sent without \"type\"",
            kind_of(other)
        )),
    }
}

fn field<'a>(o: &'a Map<String, Json>, name: &str) -> Option<&'a Json> {
    o.get(name).or_else(|| {
        o.iter()
            .find(|(k, _)| k.eq_ignore_ascii_case(name))
            .map(|(_, v)| v)
    })
}

fn object<'a>(j: &'a Json, what: &str) -> Result<&'a Map<String, Json>, String> {
    j.as_object()
        .ok_or_else(|| format!("a {what} must be a JSON object, not {}", kind_of(j)))
}

fn number(j: &Json, what: &str) -> Result<f64, String> {
    let x = match j {
        Json::Number(n) => n.as_f64(),
        Json::String(s) => s.trim().parse::<f64>().ok(),
        _ => None,
    }
    .ok_or_else(|| format!("{what} must be a number, not {}", kind_of(j)))?;
    if x.is_finite() {
        Ok(x)
    } else {
        Err(format!("{what} must be a finite number"))
    }
}

fn num_field(o: &Map<String, Json>, name: &str, what: &str) -> Result<f64, String> {
    let j = field(o, name).ok_or_else(|| format!("a {what} needs \"{name}\""))?;
    number(j, &format!("\"{name}\" of a {what}"))
}

fn xyz(j: &Json, what: &str) -> Result<[f64; 3], String> {
    let o = object(j, what)?;
    Ok([
        num_field(o, "X", what)?,
        num_field(o, "Y", what)?,
        num_field(o, "Z", what)?,
    ])
}

fn point(j: &Json) -> Result<Point3, String> {
    let [x, y, z] = xyz(j, "point")?;
    Ok(Point3::new(x, y, z))
}

fn vector(j: &Json) -> Result<Vector3, String> {
    let [x, y, z] = xyz(j, "vector")?;
    Ok(Vector3::new(x, y, z))
}

fn sub<'a>(o: &'a Map<String, Json>, name: &str, what: &str) -> Result<&'a Json, String> {
    field(o, name).ok_or_else(|| format!("a {what} needs \"{name}\""))
}

fn plane(j: &Json) -> Result<Plane, String> {
    let o = object(j, "plane")?;
    let origin = point(sub(o, "Origin", "plane")?)?;
    let x = vector(sub(o, "XAxis", "plane")?)?;
    let y = vector(sub(o, "YAxis", "plane")?)?;
    Plane::from_frame(origin, x, y).map_err(|e| format!("not a valid plane: {e}"))
}

fn interval(j: &Json) -> Result<Interval, String> {
    let o = object(j, "interval")?;
    Ok(Interval::new(
        num_field(o, "T0", "interval")?,
        num_field(o, "T1", "interval")?,
    ))
}

fn circle(o: &Map<String, Json>, what: &str) -> Result<Circle, String> {
    let radius = num_field(o, "Radius", what)?;
    let plane = match field(o, "Plane") {
        Some(p) => plane(p)?,
        None => {
            let c = point(sub(o, "Center", what)?)?;
            Plane::WORLD_XY.translated(c - Point3::ORIGIN)
        }
    };
    Circle::new(plane, radius).map_err(|e| format!("not a valid {what}: {e}"))
}

/// Reads JSON as a value of type `t` (one of the struct types, never Text or Generic).
fn value_of(j: &Json, t: DataType) -> Result<Value, String> {
    Ok(match t {
        DataType::Number => Value::Number(number(j, "a number item")?),
        DataType::Integer => {
            let x = match j {
                Json::Bool(b) => f64::from(u8::from(*b)),
                _ => number(j, "an integer item")?,
            };
            if x.fract() != 0.0 || x.abs() > 9.007_199_254_740_992e15 {
                return Err(format!("{x} is not a whole number"));
            }
            // Exact: checked whole and within ±2^53 above.
            #[allow(clippy::cast_possible_truncation)]
            Value::Integer(x as i64)
        }
        DataType::Boolean => Value::Boolean(match j {
            Json::Bool(b) => *b,
            Json::String(s) if s.eq_ignore_ascii_case("true") => true,
            Json::String(s) if s.eq_ignore_ascii_case("false") => false,
            Json::Number(n) => n.as_f64().is_some_and(|x| x != 0.0),
            other => return Err(format!("a boolean item cannot be {}", kind_of(other))),
        }),
        DataType::Text => Value::Text(text_of(j)),
        DataType::Point => Value::Point(point(j)?),
        DataType::Vector => Value::Vector(vector(j)?),
        DataType::Plane => Value::Plane(plane(j)?),
        DataType::Domain => Value::Domain(interval(j)?),
        DataType::Domain2 => {
            let o = object(j, "UV interval")?;
            Value::Domain2(UvInterval::new(
                interval(sub(o, "U", "UV interval")?)?,
                interval(sub(o, "V", "UV interval")?)?,
            ))
        }
        DataType::Line => {
            let o = object(j, "line")?;
            Value::Line(Line::new(
                point(sub(o, "From", "line")?)?,
                point(sub(o, "To", "line")?)?,
            ))
        }
        DataType::Circle => Value::Circle(circle(object(j, "circle")?, "circle")?),
        DataType::Arc => {
            let o = object(j, "arc")?;
            let c = circle(o, "arc")?;
            let angle = match field(o, "AngleDomain") {
                Some(d) => interval(d)?,
                None => match (field(o, "StartAngle"), field(o, "EndAngle")) {
                    (Some(a), Some(b)) => Interval::new(
                        number(a, "\"StartAngle\" of an arc")?,
                        number(b, "\"EndAngle\" of an arc")?,
                    ),
                    _ => Interval::new(0.0, num_field(o, "Angle", "arc")?),
                },
            };
            Value::Arc(Arc::new(c, angle).map_err(|e| format!("not a valid arc: {e}"))?)
        }
        DataType::Box => {
            let o = object(j, "box")?;
            Value::Box(OrientedBox::new(
                plane(sub(o, "Plane", "box")?)?,
                interval(sub(o, "X", "box")?)?,
                interval(sub(o, "Y", "box")?)?,
                interval(sub(o, "Z", "box")?)?,
            ))
        }
        DataType::Transform => {
            let o = object(j, "transform")?;
            let mut rows = [[0.0; 4]; 4];
            for (r, row) in rows.iter_mut().enumerate() {
                for (c, m) in row.iter_mut().enumerate() {
                    *m = num_field(o, &format!("M{r}{c}"), "transform")?;
                }
            }
            Value::Transform(Transform::from_rows(rows))
        }
        DataType::Curve | DataType::Surface | DataType::Brep | DataType::Mesh => {
            return archive::decode(t.name(), j);
        }
        DataType::Colour => return Err("colour inputs are not read in Compute form yet".into()),
        DataType::Generic => infer(j)?,
    })
}

/// A number as Json.NET writes a `double`: `5.0`, `0.25`, `NaN`, `Infinity`.
fn number_text(x: f64) -> String {
    if x.is_nan() {
        "NaN".into()
    } else if x.is_infinite() {
        if x > 0.0 { "Infinity" } else { "-Infinity" }.into()
    } else {
        let x = if x == 0.0 { 0.0 } else { x };
        serde_json::Number::from_f64(x).map_or_else(|| "NaN".into(), |n| n.to_string())
    }
}

fn num(x: f64) -> Json {
    serde_json::Number::from_f64(if x == 0.0 { 0.0 } else { x }).map_or(Json::Null, Json::Number)
}

fn xyz_json(x: f64, y: f64, z: f64) -> Json {
    json!({"X": num(x), "Y": num(y), "Z": num(z)})
}

fn point_json(p: Point3) -> Json {
    xyz_json(p.x, p.y, p.z)
}

fn vector_json(v: Vector3) -> Json {
    xyz_json(v.x, v.y, v.z)
}

fn plane_json(p: &Plane) -> Json {
    json!({
        "Origin": point_json(p.origin),
        "XAxis": vector_json(p.x_axis),
        "YAxis": vector_json(p.y_axis),
        "ZAxis": vector_json(p.z_axis),
    })
}

fn interval_json(i: Interval) -> Json {
    json!({"T0": num(i.t0), "T1": num(i.t1)})
}

/// Writes a value as Compute does: its .NET type name and its JSON text.
///
/// # Errors
/// The reason when the value has no Compute form in this build (archive geometry for now).
pub fn encode_value(value: &Value) -> Result<(&'static str, String), String> {
    let data = match value {
        Value::Number(x) => number_text(*x),
        Value::Integer(i) => i.to_string(),
        Value::Boolean(b) => b.to_string(),
        Value::Text(s) => Json::String(s.clone()).to_string(),
        Value::Point(p) => point_json(*p).to_string(),
        Value::Vector(v) => vector_json(*v).to_string(),
        Value::Plane(p) => plane_json(p).to_string(),
        Value::Domain(d) => interval_json(*d).to_string(),
        Value::Domain2(d) => json!({"U": interval_json(d.u), "V": interval_json(d.v)}).to_string(),
        Value::Transform(t) => {
            let mut o = Map::new();
            for (r, row) in t.to_rows().iter().enumerate() {
                for (c, m) in row.iter().enumerate() {
                    o.insert(format!("M{r}{c}"), num(*m));
                }
            }
            Json::Object(o).to_string()
        }
        Value::Box(b) => json!({
            "Plane": plane_json(&b.plane),
            "X": interval_json(b.x),
            "Y": interval_json(b.y),
            "Z": interval_json(b.z),
        })
        .to_string(),
        Value::Line(l) => json!({"From": point_json(l.from), "To": point_json(l.to)}).to_string(),
        Value::Circle(c) => {
            json!({"Radius": num(c.radius), "Plane": plane_json(&c.plane)}).to_string()
        }
        Value::Arc(a) => json!({
            "Radius": num(a.circle.radius),
            "Plane": plane_json(&a.circle.plane),
            "StartAngle": num(a.angle.t0),
            "EndAngle": num(a.angle.t1),
            "AngleDomain": interval_json(a.angle),
        })
        .to_string(),
        Value::Curve(_) | Value::Surface(_) | Value::Brep(_) | Value::Mesh(_) => {
            return archive::encode(value);
        }
        // As Json.NET writes a System.Drawing.Color (its TypeConverter): "R, G, B", with the
        // alpha first when the colour is not opaque.
        Value::Colour(c) if c.a == 255 => {
            Json::String(format!("{}, {}, {}", c.r, c.g, c.b)).to_string()
        }
        Value::Colour(c) => Json::String(format!("{}, {}, {}, {}", c.a, c.r, c.g, c.b)).to_string(),
    };
    let type_name = dotnet_type(value.data_type()).unwrap_or("System.Object");
    Ok((type_name, data))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn item(t: Option<&str>, data: Json) -> Json {
        match t {
            Some(t) => json!({"type": t, "data": data}),
            None => json!({"data": data}),
        }
    }

    #[test]
    fn numbers_come_as_strings_or_bare_and_cast_to_the_input_type() {
        let a = decode_item(&item(Some("System.Double"), json!("0.5")), DataType::Number);
        assert_eq!(a, Ok(Some(Value::Number(0.5))));
        let b = decode_item(&item(None, json!(5.0)), DataType::Number);
        assert_eq!(b, Ok(Some(Value::Number(5.0))));
        let c = decode_item(&item(Some("System.Int32"), json!("3")), DataType::Number);
        assert_eq!(c, Ok(Some(Value::Number(3.0))));
        let d = decode_item(&item(None, json!("7")), DataType::Integer);
        assert_eq!(d, Ok(Some(Value::Integer(7))));
        assert!(decode_item(&item(None, json!("7.5")), DataType::Integer).is_err());
        assert!(decode_item(&item(None, json!("NaN")), DataType::Number).is_err());
    }

    #[test]
    fn booleans_accept_json_text_and_python_spelling() {
        for (data, want) in [
            (json!("true"), true),
            (json!("False"), false),
            (json!(true), true),
        ] {
            let got = decode_item(&item(Some("System.Boolean"), data), DataType::Boolean);
            assert_eq!(got, Ok(Some(Value::Boolean(want))));
        }
    }

    #[test]
    fn text_is_json_text_or_bare() {
        let a = decode_item(
            &item(Some("System.String"), json!("\"abc\"")),
            DataType::Text,
        );
        assert_eq!(a, Ok(Some(Value::Text("abc".into()))));
        let b = decode_item(&item(None, json!("hello world")), DataType::Text);
        assert_eq!(b, Ok(Some(Value::Text("hello world".into()))));
    }

    #[test]
    fn null_items_and_missing_data_are_nulls() {
        assert_eq!(decode_item(&Json::Null, DataType::Number), Ok(None));
        assert_eq!(
            decode_item(&json!({"type": "System.Double"}), DataType::Number),
            Ok(None)
        );
    }

    #[test]
    fn wrong_types_and_shapes_are_reasons() {
        let e = decode_item(
            &item(Some("System.String"), json!("\"x\"")),
            DataType::Point,
        );
        assert!(e.is_err(), "{e:?}");
        let e = decode_item(&item(Some("No.Such.Type"), json!("1")), DataType::Number);
        assert_eq!(e, Err("unknown item type \"No.Such.Type\"".into()));
        let e = decode_item(&json!(5), DataType::Number);
        assert!(e.unwrap_err().contains("must be an object"));
        let e = decode_item(
            &item(Some("Rhino.Geometry.Point3d"), json!("{\"X\":1}")),
            DataType::Point,
        );
        assert_eq!(e, Err("a point needs \"Y\"".into()));
        let e = decode_item(&item(None, json!("{not json")), DataType::Point);
        assert!(e.unwrap_err().starts_with("\"data\" is not JSON"));
    }

    #[test]
    fn struct_types_round_trip() {
        let plane = Plane::from_frame(
            Point3::new(1.0, 2.0, 3.0),
            Vector3::new(0.0, 1.0, 0.0),
            Vector3::new(0.0, 0.0, 1.0),
        )
        .unwrap();
        let circle = Circle::new(plane, 2.5).unwrap();
        let values = [
            Value::Number(0.25),
            Value::Integer(-4),
            Value::Boolean(true),
            Value::Text("a \"quoted\" text".into()),
            Value::Point(Point3::new(1.0, -2.0, 3.5)),
            Value::Vector(Vector3::new(0.0, 0.0, 1.0)),
            Value::Plane(plane),
            Value::Domain(Interval::new(-1.0, 4.0)),
            Value::Line(Line::new(Point3::ORIGIN, Point3::new(1.0, 1.0, 0.0))),
            Value::Circle(circle),
            Value::Arc(Arc::new(circle, Interval::new(0.0, 1.5)).unwrap()),
            Value::Box(OrientedBox::new(
                plane,
                Interval::new(0.0, 1.0),
                Interval::new(-1.0, 1.0),
                Interval::new(2.0, 3.0),
            )),
            Value::Transform(Transform::from_rows([
                [1.0, 0.0, 0.0, 5.0],
                [0.0, 1.0, 0.0, 6.0],
                [0.0, 0.0, 1.0, 7.0],
                [0.0, 0.0, 0.0, 1.0],
            ])),
        ];
        for v in values {
            let (t, data) = encode_value(&v).unwrap();
            let back = decode_item(&json!({"type": t, "data": data}), v.data_type());
            assert_eq!(back, Ok(Some(v.clone())), "{t} {data}");
        }
    }

    #[test]
    fn numbers_are_written_as_json_net_writes_doubles() {
        assert_eq!(encode_value(&Value::Number(5.0)).unwrap().1, "5.0");
        assert_eq!(encode_value(&Value::Number(-0.0)).unwrap().1, "0.0");
        assert_eq!(encode_value(&Value::Number(f64::NAN)).unwrap().1, "NaN");
        assert_eq!(
            encode_value(&Value::Point(Point3::new(2.0, 1.5, 0.0))).unwrap(),
            (
                "Rhino.Geometry.Point3d",
                r#"{"X":2.0,"Y":1.5,"Z":0.0}"#.to_owned()
            )
        );
    }
}
