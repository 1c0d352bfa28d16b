//! File formats: scenes and LCP batches in JSON, Siconos `.dat` LCPs, and the
//! JSON output. Field names are fixed so that other tools can write and read
//! them (see the README).

pub mod fc3d;
pub mod friction;
mod output;
pub mod siconos;
pub(crate) mod strict;

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::lcp::Lcp;
use crate::scene::Scene;
use crate::Error;

pub use output::{
    basis_indices, ContactOutput, IslandOutput, LcpBatchOutput, LcpOutput, SceneOutput,
    ScenesOutput,
};

/// What an input file holds.
#[derive(Clone, Debug, PartialEq)]
pub enum Input {
    /// One scene (`{"bodies", "contacts"}`) or many (`{"scenes": [...]}`).
    Scenes(Vec<Scene>),
    /// LCPs: a JSON batch or one Siconos `.dat` problem.
    Lcps(Vec<Lcp>),
    /// Frictional problems: a JSON batch (`{"friction_problems": [...]}`)
    /// or one FrictionContact3D `.dat` problem.
    Friction(Vec<crate::FrictionProblem>),
}

/// One LCP in the JSON batch format: M as rows.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LcpRecord {
    #[serde(rename = "M")]
    /// M, row by row.
    pub m: Vec<Vec<f64>>,
    /// q.
    pub q: Vec<f64>,
}

#[derive(Deserialize)]
#[serde(untagged)]
enum JsonInput {
    Batch { problems: Vec<LcpRecord> },
    Scenes { scenes: Vec<Scene> },
    Scene(Scene),
}

/// Parses JSON text holding a scene, `{"scenes": [...]}` or
/// `{"problems": [...]}`, and checks every item. `path` names the file in errors.
///
/// # Errors
/// [`Error::Json`] (line and column) when the text is not JSON of one of
/// these shapes; [`Error::Invalid`] naming the first item and field that
/// fail their checks.
pub fn parse_json(path: &str, text: &str) -> Result<Input, Error> {
    match typed(text) {
        Some(input) => checked_items(path, input),
        None => checked(path, text),
    }
}

/// Every item of a parsed file checked (an error names the first bad one).
fn checked_items(path: &str, input: JsonInput) -> Result<Input, Error> {
    match input {
        JsonInput::Batch { problems } => {
            if problems.is_empty() {
                return Err(Error::invalid(path, "problems", "empty list"));
            }
            let lcps = problems
                .into_iter()
                .enumerate()
                .map(|(i, p)| {
                    Lcp::from_rows(&p.m, p.q).map_err(|e| match e {
                        Error::Invalid { field, reason, .. } => {
                            Error::invalid(format!("problem {i}"), field, reason)
                        }
                        other => other,
                    })
                })
                .collect::<Result<Vec<_>, _>>()?;
            Ok(Input::Lcps(lcps))
        }
        JsonInput::Scenes { scenes } => {
            if scenes.is_empty() {
                return Err(Error::invalid(path, "scenes", "empty list"));
            }
            for (i, s) in scenes.iter().enumerate() {
                s.validate(format_args!("scene {i}"))?;
            }
            Ok(Input::Scenes(scenes))
        }
        JsonInput::Scene(scene) => {
            scene.validate("scene 0")?;
            Ok(Input::Scenes(vec![scene]))
        }
    }
}

/// The fast path: a file of the right shape parsed straight into its type,
/// once. serde's derive refuses unknown fields (`deny_unknown_fields`) and a
/// field given twice in one object, and every object of the formats is a
/// derived struct, so what parses here is what [`checked`] accepts, with the
/// same numbers. None for anything else: [`checked`] then says precisely
/// what is wrong.
fn typed(text: &str) -> Option<JsonInput> {
    if let Ok(b) = serde_json::from_str::<BatchFile>(text) {
        return Some(JsonInput::Batch {
            problems: b.problems,
        });
    }
    if let Ok(s) = serde_json::from_str::<ScenesFile>(text) {
        return Some(JsonInput::Scenes { scenes: s.scenes });
    }
    serde_json::from_str::<Scene>(text)
        .ok()
        .map(JsonInput::Scene)
}

/// The checked path: parse as a generic value first so that syntax errors
/// keep their position, look for a key given twice, then pick the shape by
/// its top-level key. A value of the wrong type or shape is then named by
/// item and field (see [`shape_error`]), as the checks on values name theirs.
fn checked(path: &str, text: &str) -> Result<Input, Error> {
    let value = strict::parse_object(path, text, strict::item_of)?;
    if value.get("friction_problems").is_some() {
        return Ok(Input::Friction(friction::parse_friction_json(path, value)?));
    }
    let obj = value.as_object().expect("parse_object checked");
    let input = if obj.contains_key("problems") {
        let batch: BatchFile = serde_json::from_value(value.clone())
            .map_err(|e| shape_error(path, text, &value, Shape::Batch, e))?;
        JsonInput::Batch {
            problems: batch.problems,
        }
    } else if obj.contains_key("scenes") {
        let s: ScenesFile = serde_json::from_value(value.clone())
            .map_err(|e| shape_error(path, text, &value, Shape::Scenes, e))?;
        JsonInput::Scenes { scenes: s.scenes }
    } else if obj.contains_key("bodies") || obj.contains_key("contacts") {
        JsonInput::Scene(
            serde_json::from_value(value.clone())
                .map_err(|e| shape_error(path, text, &value, Shape::Scene, e))?,
        )
    } else {
        return Err(Error::invalid(
            path,
            "(top level)",
            "expected a key `problems` (LCP batch), `friction_problems` (frictional batch), `scenes` or `bodies` and `contacts` (scene)",
        ));
    };
    checked_items(path, input)
}

/// The three shapes of a JSON input file.
#[derive(Clone, Copy)]
enum Shape {
    Batch,
    Scenes,
    Scene,
}

/// Turns serde's error for a value of the wrong type or shape into an error
/// naming the item ("scene 0, contact 3", "problem 2") and the field
/// ("normal", "M[1][0]"). Falls back to serde's message with the position in
/// the text when the walk below finds nothing (it mirrors the types, so that
/// should not happen).
fn shape_error(
    path: &str,
    text: &str,
    value: &serde_json::Value,
    shape: Shape,
    e: serde_json::Error,
) -> Error {
    let found = match shape {
        Shape::Batch => check_batch(path, value),
        Shape::Scenes => check_scenes(path, value),
        Shape::Scene => check_scene("scene 0", value),
    };
    if let Some(err) = found {
        return err;
    }
    // Deserializing the text itself gives serde's position.
    let positioned = match shape {
        Shape::Batch => serde_json::from_str::<BatchFile>(text).err(),
        Shape::Scenes => serde_json::from_str::<ScenesFile>(text).err(),
        Shape::Scene => serde_json::from_str::<Scene>(text).err(),
    };
    Error::json(path, positioned.unwrap_or(e))
}

/// A JSON value's kind, for messages: `string "x"`, `null`, `an array`.
fn kind(v: &serde_json::Value) -> String {
    use serde_json::Value;
    match v {
        Value::Null => "null".into(),
        Value::Bool(b) => format!("boolean {b}"),
        Value::Number(n) => format!("number {n}"),
        Value::String(s) => {
            let short: String = s.chars().take(40).collect();
            format!("string {short:?}")
        }
        Value::Array(a) => format!("an array of {} entries", a.len()),
        Value::Object(_) => "an object".into(),
    }
}

type FieldError = (String, String);

/// A field's check: Ok, or the field (with its index) and what is wrong.
type FieldCheck = fn(&serde_json::Value, &str) -> Result<(), FieldError>;

fn number(v: &serde_json::Value, field: &str) -> Result<(), FieldError> {
    if v.is_number() {
        Ok(())
    } else {
        Err((
            field.into(),
            format!("expected a number, found {}", kind(v)),
        ))
    }
}

/// An array (of `len` entries when given), each entry checked by `entry`.
fn array(
    v: &serde_json::Value,
    field: &str,
    len: Option<usize>,
    entry: impl Fn(&serde_json::Value, &str) -> Result<(), FieldError>,
) -> Result<(), FieldError> {
    let Some(a) = v.as_array() else {
        return Err((
            field.into(),
            format!("expected an array, found {}", kind(v)),
        ));
    };
    if let Some(len) = len {
        if a.len() != len {
            return Err((
                field.into(),
                format!("expected {len} entries, found {}", a.len()),
            ));
        }
    }
    for (i, x) in a.iter().enumerate() {
        entry(x, &format!("{field}[{i}]"))?;
    }
    Ok(())
}

fn vec3(v: &serde_json::Value, field: &str) -> Result<(), FieldError> {
    array(v, field, Some(3), number)
}

fn index(v: &serde_json::Value, field: &str) -> Result<(), FieldError> {
    if v.as_u64().is_some_and(|i| usize::try_from(i).is_ok()) {
        Ok(())
    } else {
        Err((
            field.into(),
            format!("expected a body index (an integer ≥ 0), found {}", kind(v)),
        ))
    }
}

/// Checks the fields of an object: no others than `fields` when `closed`
/// (first, so that a misspelt key is named as unknown rather than reported
/// as its correct spelling missing), each required one present and of the
/// right form, optional ones of the right form when present.
fn object(
    v: &serde_json::Value,
    fields: &[(&str, bool, FieldCheck)],
    closed: bool,
) -> Result<(), FieldError> {
    let Some(obj) = v.as_object() else {
        return Err((
            "(item)".into(),
            format!("expected an object, found {}", kind(v)),
        ));
    };
    if closed {
        if let Some(k) = obj
            .keys()
            .find(|k| !fields.iter().any(|f| f.0 == k.as_str()))
        {
            let known: Vec<String> = fields.iter().map(|f| format!("`{}`", f.0)).collect();
            return Err((
                k.clone(),
                format!("unknown field (expected {})", known.join(", ")),
            ));
        }
    }
    for &(name, required, check) in fields {
        match obj.get(name) {
            None if required => return Err((name.into(), "missing".into())),
            None => {}
            Some(x) => check(x, name)?,
        }
    }
    Ok(())
}

fn body_fields() -> [(&'static str, bool, FieldCheck); 5] {
    [
        ("inv_mass", true, number),
        ("inv_inertia", true, |v, f| array(v, f, Some(3), vec3)),
        ("position", true, vec3),
        ("velocity", true, vec3),
        ("angular_velocity", true, vec3),
    ]
}

fn contact_fields() -> [(&'static str, bool, FieldCheck); 8] {
    [
        ("a", true, index),
        (
            "b",
            false,
            |v, f| if v.is_null() { Ok(()) } else { index(v, f) },
        ),
        ("point", true, vec3),
        ("normal", true, vec3),
        ("restitution", true, number),
        ("id", false, |v, f| {
            if v.is_null() || v.is_u64() {
                Ok(())
            } else {
                Err((
                    f.into(),
                    format!("expected an integer id ≥ 0, found {}", kind(v)),
                ))
            }
        }),
        ("friction", false, number),
        ("tangent", false, |v, f| {
            if v.is_null() {
                Ok(())
            } else {
                vec3(v, f)
            }
        }),
    ]
}

/// A list under `key` of `v`, or the error naming it.
fn list<'a>(
    item: &str,
    v: &'a serde_json::Value,
    key: &str,
) -> Result<&'a Vec<serde_json::Value>, Error> {
    match v.get(key) {
        None => Err(Error::invalid(item, key, "missing")),
        Some(x) => x.as_array().ok_or_else(|| {
            Error::invalid(item, key, format!("expected an array, found {}", kind(x)))
        }),
    }
}

fn check_scene(item: &str, v: &serde_json::Value) -> Option<Error> {
    let Some(obj) = v.as_object() else {
        return Some(Error::invalid(
            item,
            "(item)",
            format!("expected an object, found {}", kind(v)),
        ));
    };
    if let Some(k) = obj
        .keys()
        .find(|k| !["bodies", "contacts"].contains(&k.as_str()))
    {
        return Some(Error::invalid(
            item,
            k.as_str(),
            "unknown field (expected `bodies`, `contacts`)",
        ));
    }
    let (bodies, contacts) = (body_fields(), contact_fields());
    for (key, what, fields) in [
        ("bodies", "body", &bodies[..]),
        ("contacts", "contact", &contacts[..]),
    ] {
        let items = match list(item, v, key) {
            Ok(items) => items,
            Err(e) => return Some(e),
        };
        for (j, x) in items.iter().enumerate() {
            if let Err((field, reason)) = object(x, fields, true) {
                return Some(Error::invalid(format!("{item}, {what} {j}"), field, reason));
            }
        }
    }
    None
}

fn check_scenes(path: &str, v: &serde_json::Value) -> Option<Error> {
    if let Some(k) = v
        .as_object()
        .and_then(|o| o.keys().find(|k| k.as_str() != "scenes"))
    {
        return Some(Error::invalid(
            path,
            k.as_str(),
            "unknown field (expected `scenes`)",
        ));
    }
    let scenes = match list(path, v, "scenes") {
        Ok(s) => s,
        Err(e) => return Some(e),
    };
    scenes
        .iter()
        .enumerate()
        .find_map(|(i, s)| check_scene(&format!("scene {i}"), s))
}

/// A matrix given as rows of numbers (`M`, `W`).
fn rows(v: &serde_json::Value, f: &str) -> Result<(), FieldError> {
    array(v, f, None, |r, f| array(r, f, None, number))
}

/// A list of numbers (`q`, `mu`).
fn numbers(v: &serde_json::Value, f: &str) -> Result<(), FieldError> {
    array(v, f, None, number)
}

fn check_batch(path: &str, v: &serde_json::Value) -> Option<Error> {
    check_problems(
        path,
        v,
        "problems",
        &[("M", true, rows), ("q", true, numbers)],
    )
}

/// A file `{key: [problem, …]}` whose problems are objects of exactly
/// `fields`: the first fault, named by `problem i` and the field.
fn check_problems(
    path: &str,
    v: &serde_json::Value,
    key: &str,
    fields: &[(&str, bool, FieldCheck)],
) -> Option<Error> {
    if let Some(k) = v
        .as_object()
        .and_then(|o| o.keys().find(|k| k.as_str() != key))
    {
        return Some(Error::invalid(
            path,
            k.as_str(),
            format!("unknown field (expected `{key}`)"),
        ));
    }
    let problems = match list(path, v, key) {
        Ok(p) => p,
        Err(e) => return Some(e),
    };
    problems.iter().enumerate().find_map(|(i, p)| {
        object(p, fields, true)
            .err()
            .map(|(field, reason)| Error::invalid(format!("problem {i}"), field, reason))
    })
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct BatchFile {
    problems: Vec<LcpRecord>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ScenesFile {
    scenes: Vec<Scene>,
}

/// Reads an input file: `.dat` as Siconos (FrictionContact3D when its
/// header says so, see [`fc3d::is_fc3d`], else an LCP), anything else as JSON.
///
/// # Errors
/// [`Error::Io`] when the file cannot be read; [`Error::Dat`] for a
/// malformed `.dat` file; those of [`parse_json`] otherwise.
pub fn read_input(path: &Path) -> Result<Input, Error> {
    let text = std::fs::read_to_string(path).map_err(|source| Error::Io {
        path: path.to_path_buf(),
        source,
    })?;
    let name = path.display().to_string();
    if path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("dat"))
    {
        if fc3d::is_fc3d(&text) {
            Ok(Input::Friction(vec![fc3d::parse_fc3d(&name, &text)?]))
        } else {
            Ok(Input::Lcps(vec![siconos::parse_dat(&name, &text)?]))
        }
    } else {
        parse_json(&name, &text)
    }
}

/// Writes `text` to `path` atomically: a temporary file beside it, renamed
/// into place, so that a failure leaves no partial output.
///
/// # Errors
/// [`Error::Io`] when the temporary file cannot be written or renamed;
/// [`Error::Invalid`] when `path` names no file.
pub fn write_atomically(path: &Path, text: &str) -> Result<(), Error> {
    let io = |source| Error::Io {
        path: path.to_path_buf(),
        source,
    };
    let dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let file_name = path
        .file_name()
        .ok_or_else(|| Error::invalid("-o", "path", "names no file"))?;
    let tmp = dir.join(format!(
        ".{}.tmp{}",
        file_name.to_string_lossy(),
        std::process::id()
    ));
    std::fs::write(&tmp, text).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        io(e)
    })?;
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        io(e)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shapes_are_recognised_and_errors_named() {
        let s = r#"{"problems":[{"M":[[2,1],[1,2]],"q":[-5,-6]}]}"#;
        assert!(matches!(parse_json("t", s).unwrap(), Input::Lcps(v) if v.len() == 1));
        let s = r#"{"problems":[{"M":[[2,1],[1]],"q":[-5,-6]}]}"#;
        let e = parse_json("t", s).unwrap_err().to_string();
        assert!(e.contains("problem 0") && e.contains("M[1]"), "{e}");
        let scene = r#"{"bodies":[{"inv_mass":1,"inv_inertia":[[1,0,0],[0,1,0],[0,0,1]],"position":[0,1,0],"velocity":[0,-1,0],"angular_velocity":[0,0,0]}],
            "contacts":[{"a":0,"b":null,"point":[0,0,0],"normal":[0,1,0],"restitution":0.5}]}"#;
        assert!(matches!(parse_json("t", scene).unwrap(), Input::Scenes(v) if v.len() == 1));
        let bad = scene.replace("\"a\":0", "\"a\":3");
        let e = parse_json("t", &bad).unwrap_err().to_string();
        assert!(e.contains("scene 0, contact 0") && e.contains("`a`"), "{e}");
        let e = parse_json("t", "{\"problems\": [").unwrap_err().to_string();
        assert!(e.contains("line 1"), "{e}");
        let e = parse_json("t", r#"{"bodies":[{"inv_mass":"x"}],"contacts":[]}"#)
            .unwrap_err()
            .to_string();
        assert!(e.contains("inv_mass") || e.contains("invalid type"), "{e}");
    }

    #[test]
    fn malformed_json_states_its_position_once() {
        let text = "{\"problems\": [\n  {\"M\": [[1]], \"q\": [1]},\n  {\"M\": [[1]] \"q\": [1]}]}";
        let e = parse_json("t.json", text).unwrap_err();
        let Error::Json { line, column, .. } = &e else {
            panic!("not a JSON error: {e}");
        };
        assert_eq!((*line, *column), (3, 15)); // the `"` of "q"
        let text = e.to_string();
        assert_eq!(
            text,
            "t.json: malformed JSON at line 3, column 15: expected `,` or `}`"
        );
        assert_eq!(text.matches("line").count(), 1, "{text}");
        assert_eq!(text.matches("column").count(), 1, "{text}");
    }

    #[test]
    fn a_misspelt_key_is_named_as_unknown_not_its_spelling_as_missing() {
        let cases = [
            (
                r#"{"problems":[{"M":[[1]],"q":[1]},{"M":[[1]],"qq":[1]}]}"#,
                "problem 1: field `qq`: unknown field (expected `M`, `q`)",
            ),
            (
                r#"{"problems":[{"m":[[1]],"q":[1]}]}"#,
                "problem 0: field `m`: unknown field (expected `M`, `q`)",
            ),
            (
                r#"{"friction_problems":[{"W":[[1,0,0],[0,1,0],[0,0,1]],"q":[-1,0,0],"m":[0.5]}]}"#,
                "problem 0: field `m`: unknown field (expected `W`, `q`, `mu`)",
            ),
            (
                r#"{"bodies":[],"contacts":[{"a":0,"point":[0,0,0],"normal":[0,1,0],"restituion":0.5}]}"#,
                "scene 0, contact 0: field `restituion`: unknown field",
            ),
        ];
        for (text, want) in cases {
            let e = parse_json("t.json", text).unwrap_err().to_string();
            assert!(e.starts_with(want), "{want}\n{e}");
        }
        // A key truly missing is still reported as missing.
        let e = parse_json("t.json", r#"{"problems":[{"M":[[1]]}]}"#)
            .unwrap_err()
            .to_string();
        assert_eq!(e, "problem 0: field `q`: missing");
        let e = parse_json(
            "t.json",
            r#"{"friction_problems":[{"W":[[1,0,0],[0,1,0],[0,0,1]],"q":[-1,0,0]}]}"#,
        )
        .unwrap_err()
        .to_string();
        assert_eq!(e, "problem 0: field `mu`: missing");
    }
}
