//! Strict reading: a key twice in one JSON object is an error naming the
//! item and the key (serde_json's `Value` keeps the last one silently).
//! Unknown fields are refused by the shape checks in `mod.rs` and by
//! `deny_unknown_fields` on every type read.

/// The first key that appears twice in one object of the JSON `text`, with
/// the path of that object (`["scenes", "[2]", "contacts", "[1]"]`); None
/// when every object's keys are distinct (serde_json's `Value` would keep
/// only the last of two, silently). `text` is known to parse.
pub(crate) fn duplicate_key(text: &str) -> Option<(Vec<String>, String)> {
    use serde::de::{DeserializeSeed, Deserializer, MapAccess, SeqAccess, Visitor};
    struct Walk<'a>(&'a mut Vec<String>, &'a mut Option<(Vec<String>, String)>);
    impl<'de> DeserializeSeed<'de> for Walk<'_> {
        type Value = ();
        fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
            d.deserialize_any(self)
        }
    }
    impl<'de> Visitor<'de> for Walk<'_> {
        type Value = ();
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("any JSON value")
        }
        fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
            let mut seen = std::collections::HashSet::new();
            while let Some(k) = map.next_key::<String>()? {
                if !seen.insert(k.clone()) && self.1.is_none() {
                    *self.1 = Some((self.0.clone(), k.clone()));
                }
                self.0.push(k);
                map.next_value_seed(Walk(&mut *self.0, &mut *self.1))?;
                self.0.pop();
            }
            Ok(())
        }
        fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<(), A::Error> {
            let mut i = 0usize;
            loop {
                self.0.push(format!("[{i}]"));
                let more = seq.next_element_seed(Walk(&mut *self.0, &mut *self.1))?;
                self.0.pop();
                if more.is_none() {
                    return Ok(());
                }
                i += 1;
            }
        }
        fn visit_bool<E>(self, _: bool) -> Result<(), E> {
            Ok(())
        }
        fn visit_i64<E>(self, _: i64) -> Result<(), E> {
            Ok(())
        }
        fn visit_u64<E>(self, _: u64) -> Result<(), E> {
            Ok(())
        }
        fn visit_f64<E>(self, _: f64) -> Result<(), E> {
            Ok(())
        }
        fn visit_str<E>(self, _: &str) -> Result<(), E> {
            Ok(())
        }
        fn visit_unit<E>(self) -> Result<(), E> {
            Ok(())
        }
    }
    let (mut path, mut found) = (Vec::new(), None);
    let mut d = serde_json::Deserializer::from_str(text);
    Walk(&mut path, &mut found).deserialize(&mut d).ok()?;
    found
}

/// Strict parsing of a file's JSON text, shared by every format: syntax
/// errors keep their position, a key twice in one object is an error naming
/// the item (`item_of(path, json path)`) and the key, and the top level must
/// be an object.
pub(crate) fn parse_object(
    path: &str,
    text: &str,
    item_of: fn(&str, &[String]) -> String,
) -> Result<serde_json::Value, crate::Error> {
    use crate::Error;
    let value: serde_json::Value = serde_json::from_str(text).map_err(|e| Error::json(path, e))?;
    if let Some((at, key)) = duplicate_key(text) {
        return Err(Error::invalid(
            item_of(path, &at),
            key,
            "appears twice in one object (each field once)",
        ));
    }
    if !value.is_object() {
        return Err(Error::invalid(
            path,
            "(top level)",
            "expected a JSON object",
        ));
    }
    Ok(value)
}

/// The item a JSON path names, in the words of the other errors: `problem
/// 4` (of an LCP or a friction batch), `scene 2, contact 1`, `scene 0,
/// body 3` (a single scene is scene 0), the file itself at the top level.
pub(super) fn item_of(file: &str, at: &[String]) -> String {
    let index = |s: &String| s.trim_matches(|c| c == '[' || c == ']').to_string();
    let (scene, rest) = match at {
        [k, i, rest @ ..] if k == "scenes" => (Some(index(i)), rest),
        [k, i, ..] if k == "problems" || k == "friction_problems" => {
            return format!("problem {}", index(i))
        }
        [] => return file.to_string(),
        rest => (Some("0".to_string()), rest),
    };
    let scene = format!("scene {}", scene.unwrap_or_default());
    match rest {
        [k, i, ..] if k == "bodies" => format!("{scene}, body {}", index(i)),
        [k, i, ..] if k == "contacts" => format!("{scene}, contact {}", index(i)),
        _ => scene,
    }
}

#[cfg(test)]
mod tests {
    use super::super::parse_json;

    fn err(text: &str) -> String {
        parse_json("f.json", text).unwrap_err().to_string()
    }

    const BODY: &str = r#""inv_mass":1,"inv_inertia":[[1,0,0],[0,1,0],[0,0,1]],"position":[0,1,0],"velocity":[0,0,0],"angular_velocity":[0,0,0]"#;
    const CONTACT: &str = r#""a":0,"b":null,"point":[0,0,0],"normal":[0,1,0],"restitution":0.5"#;

    #[test]
    fn a_key_twice_is_named_with_its_item_at_every_level() {
        let cases = [
            (
                r#"{"problems":[{"M":[[1]],"q":[1]}],"problems":[]}"#.to_string(),
                "f.json: field `problems`",
            ),
            (
                r#"{"problems":[{"M":[[1]],"q":[1]},{"M":[[1]],"q":[1],"q":[2]}]}"#.to_string(),
                "problem 1: field `q`",
            ),
            (
                r#"{"friction_problems":[{"W":[[1,0,0],[0,1,0],[0,0,1]],"q":[-1,0,0],"mu":[1],"mu":[2]}]}"#.to_string(),
                "problem 0: field `mu`",
            ),
            (
                format!(r#"{{"bodies":[{{{BODY},"position":[0,0,0]}}],"contacts":[]}}"#),
                "scene 0, body 0: field `position`",
            ),
            (
                format!(
                    r#"{{"scenes":[{{"bodies":[{{{BODY}}}],"contacts":[{{{CONTACT},"a":0}}]}}]}}"#
                ),
                "scene 0, contact 0: field `a`",
            ),
            (
                format!(
                    r#"{{"scenes":[{{"bodies":[],"contacts":[]}},{{"bodies":[],"bodies":[],"contacts":[]}}]}}"#
                ),
                "scene 1: field `bodies`",
            ),
        ];
        for (text, want) in cases {
            let e = err(&text);
            assert!(e.contains(want) && e.contains("twice"), "{want}: {e}");
        }
    }

    #[test]
    fn unknown_fields_are_named_everywhere() {
        let cases = [
            (
                format!(r#"{{"bodies":[{{{BODY}}}],"contacts":[{{{CONTACT},"fricton":0.5}}]}}"#),
                "scene 0, contact 0: field `fricton`",
            ),
            (
                format!(r#"{{"bodies":[{{{BODY},"mass":2}}],"contacts":[]}}"#),
                "scene 0, body 0: field `mass`",
            ),
            (
                r#"{"bodies":[],"contacts":[],"gravity":[0,-9.8,0]}"#.to_string(),
                "scene 0: field `gravity`",
            ),
            (
                r#"{"scenes":[{"bodies":[],"contacts":[]}],"dt":0.01}"#.to_string(),
                "f.json: field `dt`",
            ),
            (
                r#"{"problems":[{"M":[[1]],"q":[1],"w":[0]}]}"#.to_string(),
                "problem 0: field `w`",
            ),
        ];
        for (text, want) in cases {
            let e = err(&text);
            assert!(
                e.contains(want) && e.contains("unknown field"),
                "{want}: {e}"
            );
        }
        // The optional id of a contact is known, and must be an integer.
        let ok = format!(r#"{{"bodies":[{{{BODY}}}],"contacts":[{{{CONTACT},"id":7}}]}}"#);
        parse_json("f.json", &ok).unwrap();
        let bad = format!(r#"{{"bodies":[{{{BODY}}}],"contacts":[{{{CONTACT},"id":-1}}]}}"#);
        assert!(err(&bad).contains("field `id`"), "{}", err(&bad));
        // Friction and a tangent are known; friction must be a number.
        let ok = format!(
            r#"{{"bodies":[{{{BODY}}}],"contacts":[{{{CONTACT},"friction":0.5,"tangent":[1,0,0]}}]}}"#
        );
        parse_json("f.json", &ok).unwrap();
        let bad = format!(r#"{{"bodies":[{{{BODY}}}],"contacts":[{{{CONTACT},"friction":"x"}}]}}"#);
        assert!(err(&bad).contains("field `friction`"), "{}", err(&bad));
    }
}
