//! The world file: one world (`{"gravity": …, "bodies": [...]}`) or several
//! (`{"worlds": [...]}`), read strictly as the scene formats are: unknown
//! fields refused, a key twice in one object refused, every error naming the
//! item ("world 0, body 3") and the field; never a panic on user data.
//!
//! ```json
//! {"gravity": [0, -9.81, 0], "contact_margin": 0.005,
//!  "sleep": {"steps": 60, "linear": 0.01, "angular": 0.05},
//!  "bodies": [
//!   {"shape": {"plane": {"normal": [0, 1, 0]}}, "fixed": true, "position": [0, 0, 0], "friction": 0.5},
//!   {"shape": {"box": {"half_extents": [0.5, 0.5, 0.5]}}, "position": [0, 0.5, 0],
//!    "orientation": [0, 0, 0, 1], "velocity": [2, 0, 0], "density": 1000, "friction": 0.5}]}
//! ```

use serde::de::DeserializeOwned;
use serde_json::Value;

use super::{RigidBody, Shape, Sleep, World};
use crate::Error;

/// Relative tolerance on unit normals and quaternions.
const UNIT_TOL: f64 = 1e-6;

/// Parses a world file's text; `path` names the file in errors.
///
/// # Errors
/// [`Error::Json`] when the text is not JSON; [`Error::Invalid`] naming the
/// world, the body and the field that fail their checks.
pub fn parse_worlds(path: &str, text: &str) -> Result<Vec<World>, Error> {
    let value = crate::io::strict::parse_object(path, text, item_of)?;
    let obj = value.as_object().expect("parse_object checked");
    let worlds: Vec<&Value> = match obj.get("worlds") {
        Some(Value::Array(list)) if obj.len() == 1 => list.iter().collect(),
        Some(_) if obj.len() > 1 => {
            return Err(Error::invalid(
                path,
                "worlds",
                "a file of worlds holds only the key `worlds`",
            ))
        }
        Some(_) => return Err(Error::invalid(path, "worlds", "expected a list of worlds")),
        None => vec![&value],
    };
    if worlds.is_empty() {
        return Err(Error::invalid(path, "worlds", "empty list"));
    }
    worlds
        .into_iter()
        .enumerate()
        .map(|(i, v)| read_world(&format!("world {i}"), v))
        .collect()
}

/// The item a JSON path names: `world 2, body 1`, `world 0`.
fn item_of(file: &str, at: &[String]) -> String {
    let index = |s: &String| s.trim_matches(|c| c == '[' || c == ']').to_string();
    let (world, rest) = match at {
        [k, i, rest @ ..] if k == "worlds" => (index(i), rest),
        [] => return file.to_string(),
        rest => ("0".to_string(), rest),
    };
    match rest {
        [k, i, ..] if k == "bodies" => format!("world {world}, body {}", index(i)),
        _ => format!("world {world}"),
    }
}

/// One world from its JSON value, checked.
fn read_world(item: &str, v: &Value) -> Result<World, Error> {
    // Bodies first, so that a body's fault is named by the body.
    if let Some(Value::Array(bodies)) = v.get("bodies") {
        for (i, b) in bodies.iter().enumerate() {
            from_value::<RigidBody>(&format!("{item}, body {i}"), b, body_field)?;
        }
    }
    let world: World = from_value(item, v, world_field)?;
    world.validate(item)?;
    Ok(world)
}

/// Deserialises `v`; on failure names the field: the one serde names
/// (unknown, missing) when it is this object's, else the first whose value
/// has the wrong type (a nested object's key unknown or missing included).
fn from_value<T: DeserializeOwned>(
    item: &str,
    v: &Value,
    field_ok: fn(&str, &Value) -> bool,
) -> Result<T, Error> {
    let err = match serde_json::from_value::<T>(v.clone()) {
        Ok(t) => return Ok(t),
        Err(e) => e.to_string(),
    };
    let Some(obj) = v.as_object() else {
        return Err(Error::invalid(item, "(item)", "expected a JSON object"));
    };
    let bad = obj
        .iter()
        .find(|(k, val)| !field_ok(k, val))
        .map(|(k, _)| k.clone());
    let named = err.starts_with("unknown field") || err.starts_with("missing field");
    let field = match err.split('`').nth(1) {
        // serde names the key, unknown or missing, of this object; a key of
        // a nested one (`shape`'s, `sleep`'s) is named by the field holding it.
        Some(k) if named && (obj.contains_key(k) || bad.is_none()) => k.to_string(),
        _ => bad.unwrap_or_else(|| "(item)".into()),
    };
    Err(Error::invalid(item, field, err))
}

fn is<T: DeserializeOwned>(v: &Value) -> bool {
    serde_json::from_value::<T>(v.clone()).is_ok()
}

/// Whether a world-level field's value has its type.
fn world_field(key: &str, v: &Value) -> bool {
    match key {
        "gravity" => is::<[f64; 3]>(v),
        "contact_margin" => is::<f64>(v),
        "sleep" => is::<Sleep>(v),
        "bodies" => v.is_array(),
        _ => true,
    }
}

/// Whether a body field's value has its type.
fn body_field(key: &str, v: &Value) -> bool {
    match key {
        "shape" => is::<Shape>(v),
        "fixed" | "asleep" => v.is_boolean(),
        "position" | "velocity" | "angular_velocity" => is::<[f64; 3]>(v),
        "orientation" => is::<[f64; 4]>(v),
        "mass" | "density" => is::<Option<f64>>(v),
        "inertia" => is::<Option<[f64; 3]>>(v),
        "friction" | "restitution" => is::<f64>(v),
        _ => true,
    }
}

fn finite(item: &str, field: &str, v: &[f64]) -> Result<(), Error> {
    match v.iter().position(|x| !x.is_finite()) {
        Some(i) if v.len() > 1 => Err(Error::invalid(
            item,
            format!("{field}[{i}]"),
            "not a finite number",
        )),
        Some(_) => Err(Error::invalid(item, field, "not a finite number")),
        None => Ok(()),
    }
}

fn positive(item: &str, field: &str, v: f64) -> Result<(), Error> {
    finite(item, field, &[v])?;
    if v <= 0.0 {
        return Err(Error::invalid(item, field, format!("{v} is not positive")));
    }
    Ok(())
}

/// Checks a world's fields (see [`World::validate`]).
pub(super) fn validate_world(w: &World, item: &str) -> Result<(), Error> {
    finite(item, "gravity", &w.gravity)?;
    finite(item, "contact_margin", &[w.contact_margin])?;
    if w.contact_margin < 0.0 {
        return Err(Error::invalid(item, "contact_margin", "negative"));
    }
    positive(item, "sleep.linear", w.sleep.linear)?;
    positive(item, "sleep.angular", w.sleep.angular)?;
    if w.bodies.len() > super::collide::MAX_BODIES {
        return Err(Error::invalid(
            item,
            "bodies",
            format!(
                "{} bodies; at most {} per world",
                w.bodies.len(),
                super::collide::MAX_BODIES
            ),
        ));
    }
    for (i, b) in w.bodies.iter().enumerate() {
        // The body's name is formatted only for the error (every step
        // checks every world).
        if validate_body(b, item).is_err() {
            validate_body(b, &format!("{item}, body {i}"))?;
        }
    }
    Ok(())
}

/// Checks one body's fields.
fn validate_body(b: &RigidBody, item: &str) -> Result<(), Error> {
    match b.shape {
        Shape::Sphere { radius } => positive(item, "shape.sphere.radius", radius)?,
        Shape::Box { half_extents } => {
            for (k, h) in half_extents.iter().enumerate() {
                // The field's name is formatted only for the error.
                if !(h.is_finite() && *h > 0.0) {
                    positive(item, &format!("shape.box.half_extents[{k}]"), *h)?;
                }
            }
        }
        Shape::Plane { normal } => {
            finite(item, "shape.plane.normal", &normal)?;
            let len = glam::DVec3::from_array(normal).length();
            if (len - 1.0).abs() > UNIT_TOL {
                return Err(Error::invalid(
                    item,
                    "shape.plane.normal",
                    format!("not a unit vector (length {len})"),
                ));
            }
            if !b.fixed {
                return Err(Error::invalid(item, "fixed", "a plane must be fixed"));
            }
        }
    }
    finite(item, "position", &b.position)?;
    finite(item, "orientation", &b.orientation)?;
    let len = b.orientation.iter().map(|x| x * x).sum::<f64>().sqrt();
    if (len - 1.0).abs() > UNIT_TOL {
        return Err(Error::invalid(
            item,
            "orientation",
            format!("not a unit quaternion (length {len})"),
        ));
    }
    finite(item, "velocity", &b.velocity)?;
    finite(item, "angular_velocity", &b.angular_velocity)?;
    if !b.fixed {
        match (b.mass, b.density) {
            (Some(m), None) => positive(item, "mass", m)?,
            (None, Some(d)) => positive(item, "density", d)?,
            (Some(_), Some(_)) => {
                return Err(Error::invalid(
                    item,
                    "density",
                    "give mass or density, not both",
                ))
            }
            (None, None) => {
                return Err(Error::invalid(
                    item,
                    "mass",
                    "a dynamic body needs mass or density",
                ))
            }
        }
        if let Some(i) = b.inertia {
            for (k, v) in i.iter().enumerate() {
                positive(item, &format!("inertia[{k}]"), *v)?;
            }
        }
    }
    finite(item, "friction", &[b.friction])?;
    if b.friction < 0.0 {
        return Err(Error::invalid(item, "friction", "negative"));
    }
    if !b.restitution.is_finite() || !(0.0..=1.0).contains(&b.restitution) {
        return Err(Error::invalid(
            item,
            "restitution",
            format!("{} is not in [0, 1]", b.restitution),
        ));
    }
    Ok(())
}

/// The worlds as JSON (`{"worlds": [...]}`), readable by [`parse_worlds`].
pub fn worlds_to_json(worlds: &[World]) -> String {
    #[derive(serde::Serialize)]
    struct File<'a> {
        worlds: &'a [World],
    }
    serde_json::to_string_pretty(&File { worlds }).expect("worlds serialise")
}

#[cfg(test)]
mod tests {
    use super::*;

    const PLANE: &str = r#"{"shape":{"plane":{"normal":[0,1,0]}},"fixed":true,"position":[0,0,0]}"#;
    const BALL: &str = r#"{"shape":{"sphere":{"radius":0.5}},"position":[0,1,0],"mass":1}"#;

    fn err(text: &str) -> String {
        parse_worlds("w.json", text).unwrap_err().to_string()
    }

    #[test]
    fn a_world_reads_and_round_trips() {
        let text = format!(r#"{{"gravity":[0,-10,0],"bodies":[{PLANE},{BALL}]}}"#);
        let w = parse_worlds("w.json", &text).unwrap();
        assert_eq!(w.len(), 1);
        assert_eq!(w[0].bodies.len(), 2);
        assert_eq!(w[0].bodies[1].shape, Shape::Sphere { radius: 0.5 });
        let again = parse_worlds("w.json", &worlds_to_json(&w)).unwrap();
        assert_eq!(again, w);
    }

    #[test]
    fn bad_worlds_are_named_by_item_and_field() {
        let cases = [
            (
                format!(r#"{{"bodies":[{PLANE},{{"shape":{{"sphere":{{"radius":-1}}}},"position":[0,1,0],"mass":1}}]}}"#),
                "world 0, body 1: field `shape.sphere.radius`",
            ),
            (
                format!(r#"{{"bodies":[{PLANE},{{"shape":{{"sphere":{{"radius":1}}}},"position":[0,1,0],"mass":1,"colour":3}}]}}"#),
                "world 0, body 1: field `colour`",
            ),
            (
                format!(r#"{{"bodies":[{PLANE},{{"shape":{{"sphere":{{"radius":1}}}},"position":[0,1,0],"mass":1,"mass":2}}]}}"#),
                "world 0, body 1: field `mass`",
            ),
            (
                format!(r#"{{"worlds":[{{"bodies":[{BALL}]}},{{"bodies":[{PLANE},{{"shape":{{"sphere":{{"radius":1}}}},"position":"up","mass":1}}]}}]}}"#),
                "world 1, body 1: field `position`",
            ),
            (
                r#"{"bodies":[{"shape":{"sphere":{"radius":1}},"position":[0,1,0]}]}"#.to_string(),
                "world 0, body 0: field `mass`",
            ),
            (
                r#"{"bodies":[{"shape":{"plane":{"normal":[0,2,0]}},"fixed":true,"position":[0,0,0]}]}"#.to_string(),
                "world 0, body 0: field `shape.plane.normal`",
            ),
            (
                r#"{"bodies":[{"shape":{"plane":{"normal":[0,1,0]}},"position":[0,0,0]}]}"#.to_string(),
                "world 0, body 0: field `fixed`",
            ),
            (
                format!(r#"{{"bodies":[{BALL}],"gravity":[0,-10]}}"#),
                "world 0: field `gravity`",
            ),
            (
                r#"{"bodies":[{"shape":{"sphere":{"radius":1}},"position":[0,1,0],"mass":1,"orientation":[0,0,0,2]}]}"#.to_string(),
                "world 0, body 0: field `orientation`",
            ),
            (
                r#"{"bodies":[{"shape":{"sphere":{"radius":1}},"position":[0,1,0],"mass":1,"restitution":1.5}]}"#.to_string(),
                "world 0, body 0: field `restitution`",
            ),
            (r#"{"worlds":[]}"#.to_string(), "w.json: field `worlds`"),
            (
                r#"{"bodies":[{"shape":{"box":{"half_extent":[1,1,1]}},"position":[0,1,0],"mass":1}]}"#.to_string(),
                "world 0, body 0: field `shape`: unknown field `half_extent`",
            ),
            (
                r#"{"bodies":[{"shape":{"sphere":{}},"position":[0,1,0],"mass":1}]}"#.to_string(),
                "world 0, body 0: field `shape`: missing field `radius`",
            ),
            (
                format!(r#"{{"bodies":[{BALL}],"sleep":{{"step":3}}}}"#),
                "world 0: field `sleep`: unknown field `step`",
            ),
        ];
        for (text, want) in cases {
            let e = err(&text);
            assert!(e.starts_with(want), "{text}\n  gave: {e}\n  want: {want}");
        }
        assert!(err("[1,2]").contains("expected a JSON object"));
        assert!(err("{").contains("malformed JSON"));
    }
}
