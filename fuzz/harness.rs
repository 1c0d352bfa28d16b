//! The readers' fuzzing harness, one module shared by the seeded mutation
//! run (`cargo run --release --example fuzz_readers`), its short run in the
//! tests (tests/fuzz_readers.rs) and the libFuzzer targets
//! (fuzz/fuzz_targets/). It is no part of the library's API.
//!
//! [`check`] runs one reader on one input and judges the answer: an input
//! accepted must pass its type's own checks; one refused must be refused
//! with an error that names the item and the field ([`named`]). [`mutate`]
//! makes inputs from a reader's seeds; [`run`] drives both, catching panics
//! and timing every input.
#![allow(dead_code)] // each of the three users takes a part

use std::path::Path;
use std::time::{Duration, Instant};

use lcpbatch::generate::Rng;
use lcpbatch::io::{fc3d, parse_json, siconos, Input};
use lcpbatch::world::format::parse_worlds;
use lcpbatch::{Error, World};
use serde_json::Value;

/// The five readers. The three JSON formats share one entry point
/// ([`parse_json`], which tells them apart by their top-level key) but
/// each has its own seeds; `.dat` is told LCP or FrictionContact3D by its
/// header, as `lcpbatch solve` does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reader {
    /// `{"problems": [...]}`.
    Lcp,
    /// A scene or `{"scenes": [...]}`.
    Scene,
    /// `{"friction_problems": [...]}`.
    Friction,
    /// A world file (`lcpbatch simulate --world FILE`).
    World,
    /// A Siconos `.dat` file, LCP or FrictionContact3D.
    Dat,
}

impl Reader {
    /// Every reader.
    pub const ALL: [Reader; 5] = [
        Reader::Lcp,
        Reader::Scene,
        Reader::Friction,
        Reader::World,
        Reader::Dat,
    ];

    /// Its name, which is also its folder under fuzz/corpus/.
    pub fn name(self) -> &'static str {
        match self {
            Reader::Lcp => "lcp",
            Reader::Scene => "scene",
            Reader::Friction => "friction",
            Reader::World => "world",
            Reader::Dat => "dat",
        }
    }

    /// The reader of that name.
    pub fn from_name(name: &str) -> Option<Reader> {
        Reader::ALL.into_iter().find(|r| r.name() == name)
    }

    /// The file name the reader is given (errors name it).
    fn file(self) -> &'static str {
        if self == Reader::Dat {
            "fuzz.dat"
        } else {
            "fuzz.json"
        }
    }
}

/// What a reader accepted.
enum Read {
    Input(Input),
    Worlds(Vec<World>),
}

fn read(reader: Reader, text: &str) -> Result<Read, Error> {
    let file = reader.file();
    match reader {
        Reader::Dat if fc3d::is_fc3d(text) => {
            fc3d::parse_fc3d(file, text).map(|p| Read::Input(Input::Friction(vec![p])))
        }
        Reader::Dat => siconos::parse_dat(file, text).map(|l| Read::Input(Input::Lcps(vec![l]))),
        Reader::World => parse_worlds(file, text).map(Read::Worlds),
        _ => parse_json(file, text).map(Read::Input),
    }
}

/// The accepted value's own checks, which every solve runs again.
fn revalidate(read: &Read) -> Result<(), Error> {
    match read {
        Read::Input(Input::Lcps(v)) => v.iter().try_for_each(|l| l.validate("problem")),
        Read::Input(Input::Friction(v)) => v.iter().try_for_each(|p| p.validate("problem")),
        Read::Input(Input::Scenes(v)) => v.iter().try_for_each(|s| s.validate("scene")),
        Read::Worlds(v) => v.iter().try_for_each(|w| w.validate("world")),
    }
}

/// Runs `reader` on `text`: Ok(true) when it accepts a value that passes
/// its own checks, Ok(false) when it refuses with an error naming the item
/// and the field; else what is wrong. A panic of the reader is not caught
/// here.
pub fn check(reader: Reader, text: &str) -> Result<bool, String> {
    match read(reader, text) {
        Ok(read) => revalidate(&read)
            .map(|()| true)
            .map_err(|e| format!("accepted, but fails its check: {e}")),
        Err(e) => named(reader, text, &e)
            .map(|()| false)
            .map_err(|why| format!("{why}: {e}")),
    }
}

/// The field names of the `.dat` formats (src/io/siconos.rs and fc3d.rs).
const DAT_FIELDS: [&str; 20] = [
    "n",
    "storage",
    "size0",
    "size1",
    "M",
    "q",
    "nbblocks",
    "blocknumber0",
    "blocknumber1",
    "blocksize0",
    "blocksize1",
    "filled1",
    "filled2",
    "index1_data",
    "index2_data",
    "block",
    "d",
    "n_c",
    "W",
    "mu",
];

/// Whether a refusal names the item and the field, from the shape of
/// [`Error`]:
/// - `Invalid { item, field, reason }`: `item` is the file or an item of
///   the format's words (`problem 3`; `scene 0, contact 2`; `world 1, body
///   4`), the words fitting the file's top-level keys (a friction batch's
///   problem is no scene); `field` is not empty, and the stand-ins
///   `(item)` and `(top level)` come only with "expected …" (the item or
///   the file is of the wrong kind altogether);
/// - `Json { line, .. }`: only for text that is not JSON at all (a file of
///   the wrong shape must be named by item and field, not by serde's
///   words), and at a real position (line ≥ 1);
/// - `Dat { path, message }`: from the `.dat` reader, naming the file and
///   one of the format's fields ([`DAT_FIELDS`]);
/// - any other variant: never from a reader.
pub fn named(reader: Reader, text: &str, e: &Error) -> Result<(), String> {
    match e {
        Error::Invalid {
            item,
            field,
            reason,
        } => {
            let words = item_words(reader, text);
            if item != reader.file() && !item_named(item, &words) {
                return Err(format!(
                    "item `{item}` is not one of {words:?} nor the file"
                ));
            }
            // A key "" is named as it is, `` (unknown, or given twice).
            let key = reason.starts_with("unknown field") || reason.contains("twice");
            if (field.is_empty() && !key) || reason.is_empty() {
                return Err("empty field or reason".into());
            }
            let stand_in = field == "(item)" || field == "(top level)";
            if stand_in && !reason.starts_with("expected") {
                return Err(format!("field `{field}` names no field"));
            }
            Ok(())
        }
        Error::Json { line, .. } => {
            if serde_json::from_str::<Value>(text).is_ok() {
                Err("JSON text refused in serde's words, not by item and field".into())
            } else if *line == 0 {
                Err("malformed JSON at line 0".into())
            } else {
                Ok(())
            }
        }
        Error::Dat { path, message } if reader == Reader::Dat => {
            let words = message.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'));
            if path != reader.file() {
                Err("names another file".into())
            } else if !words.into_iter().any(|w| DAT_FIELDS.contains(&w)) {
                Err("names no field of the format".into())
            } else {
                Ok(())
            }
        }
        _ => Err("an error of a kind no reader gives".into()),
    }
}

/// The words an item of this file may be named by: `problem` in a file of
/// problems, `scene` in one of scenes (or a scene), `world` in a world file.
fn item_words(reader: Reader, text: &str) -> Vec<&'static str> {
    match reader {
        Reader::World => vec!["world"],
        Reader::Dat => vec![],
        _ => {
            let top =
                serde_json::from_str::<serde_json::Map<String, Value>>(text).unwrap_or_default();
            let problems = top.contains_key("problems") || top.contains_key("friction_problems");
            let mut words = Vec::new();
            if problems {
                words.push("problem");
            }
            if top.contains_key("scenes") || !problems {
                words.push("scene");
            }
            words
        }
    }
}

/// `word N`, then any number of `, body N` or `, contact N`.
fn item_named(item: &str, words: &[&str]) -> bool {
    let indexed = |part: &str, words: &[&str]| {
        part.split_once(' ')
            .is_some_and(|(w, n)| words.contains(&w) && n.parse::<usize>().is_ok())
    };
    let mut parts = item.split(", ");
    parts.next().is_some_and(|p| indexed(p, words))
        && parts.all(|p| indexed(p, &["body", "contact"]))
}

/// Numbers, and things in a number's place, that readers must refuse or
/// take: huge, tiny, NaN, infinite, negative, empty, not numbers at all.
const ODD_NUMBERS: [&str; 24] = [
    "1e400",
    "-1e400",
    "1e308",
    "-1.7976931348623157e308",
    "4.9e-324",
    "1e-400",
    "NaN",
    "nan",
    "inf",
    "-inf",
    "-1",
    "-0",
    "0",
    "",
    "99999999999",
    "18446744073709551616",
    "10000",
    "3333",
    "0.5",
    "-3.5e2",
    "\"x\"",
    "null",
    "[]",
    "{}",
];

/// The keys of the JSON formats, for renames into a neighbour's key.
const KEYS: [&str; 30] = [
    "problems",
    "friction_problems",
    "scenes",
    "worlds",
    "M",
    "W",
    "q",
    "mu",
    "bodies",
    "contacts",
    "inv_mass",
    "inv_inertia",
    "position",
    "velocity",
    "angular_velocity",
    "a",
    "b",
    "point",
    "normal",
    "restitution",
    "friction",
    "tangent",
    "id",
    "shape",
    "sphere",
    "box",
    "plane",
    "mass",
    "gravity",
    "sleep",
];

fn pick<'a, T>(rng: &mut Rng, v: &'a [T]) -> &'a T {
    &v[rng.int(0, v.len() - 1)]
}

/// Largest input made, so that splices cannot grow without bound.
const MAX_LEN: usize = 1 << 16;

/// One input from `seeds` (the reader's): a seed, for JSON often changed
/// in its structure first (a key deleted, renamed or added, a value
/// replaced, an array emptied or grown, a value nested deep), then one to
/// four changes to its text (bits flipped, bytes set, ranges deleted or
/// repeated, splices from another seed, numbers replaced by odd ones,
/// truncation, deep nesting, a key renamed, deleted or given twice).
pub fn mutate(rng: &mut Rng, reader: Reader, seeds: &[String]) -> String {
    let mut text = pick(rng, seeds).clone();
    if reader != Reader::Dat && rng.int(0, 2) > 0 {
        if let Ok(mut v) = serde_json::from_str::<Value>(&text) {
            for _ in 0..rng.int(1, 3) {
                mutate_value(rng, &mut v);
            }
            text = if rng.int(0, 1) == 0 {
                v.to_string()
            } else {
                serde_json::to_string_pretty(&v).unwrap_or(text)
            };
        }
    }
    let mut b = text.into_bytes();
    for _ in 0..rng.int(0, 3) {
        mutate_bytes(rng, reader, &mut b, seeds);
        b.truncate(MAX_LEN);
    }
    String::from_utf8_lossy(&b).into_owned()
}

/// Every node of `v`, as paths of object keys and array indices.
fn nodes(v: &Value, at: &mut Vec<Step>, out: &mut Vec<Vec<Step>>) {
    out.push(at.clone());
    match v {
        Value::Object(o) => {
            for (k, x) in o {
                at.push(Step::Key(k.clone()));
                nodes(x, at, out);
                at.pop();
            }
        }
        Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                at.push(Step::Index(i));
                nodes(x, at, out);
                at.pop();
            }
        }
        _ => {}
    }
}

#[derive(Clone)]
enum Step {
    Key(String),
    Index(usize),
}

fn node<'a>(v: &'a mut Value, path: &[Step]) -> &'a mut Value {
    path.iter().fold(v, |v, s| match s {
        Step::Key(k) => &mut v[k.as_str()],
        Step::Index(i) => &mut v[*i],
    })
}

/// A misspelling of `key`: a letter dropped, doubled or changed in case,
/// or a neighbour's key.
fn misspelt(rng: &mut Rng, key: &str) -> String {
    let c: Vec<char> = key.chars().collect();
    let i = rng.int(0, c.len().saturating_sub(1));
    match rng.int(0, 3) {
        0 if !c.is_empty() => c[..i].iter().chain(&c[i + 1..]).collect(),
        1 if !c.is_empty() => c[..=i].iter().chain(&c[i..]).collect(),
        2 => key.to_uppercase(),
        _ => pick(rng, &KEYS).to_string(),
    }
}

fn odd_value(rng: &mut Rng) -> Value {
    match rng.int(0, 9) {
        0 => Value::Null,
        1 => Value::Bool(true),
        2 => Value::String(String::new()),
        3 => Value::Array(Vec::new()),
        4 => Value::Object(Default::default()),
        5 => (0..rng.int(1, 2000))
            .map(|i| Value::from(i as f64))
            .collect(),
        6 => Value::from(u64::MAX),
        7 => Value::from(-1),
        _ => Value::from(*pick(rng, &[0.0, -0.0, 1e308, -1e308, 5e-324, 1.5])),
    }
}

/// One change to the structure of a JSON value.
fn mutate_value(rng: &mut Rng, v: &mut Value) {
    let mut all: Vec<Vec<Step>> = Vec::new();
    nodes(v, &mut Vec::new(), &mut all);
    let path: &Vec<Step> = pick(rng, &all);
    let target = node(v, path);
    match (rng.int(0, 6), target) {
        (op @ (0 | 1), Value::Object(o)) if !o.is_empty() => {
            // A key deleted, or renamed (misspelt).
            let k = o.keys().nth(rng.int(0, o.len() - 1)).cloned();
            let x = k.as_ref().and_then(|k| o.remove(k)).unwrap_or_default();
            if op == 1 {
                o.insert(misspelt(rng, &k.unwrap_or_default()), x);
            }
        }
        (2, Value::Object(o)) => {
            o.insert(pick(rng, &KEYS).to_string(), odd_value(rng));
        }
        (3, Value::Array(a)) if !a.is_empty() => {
            let i = rng.int(0, a.len() - 1);
            if rng.int(0, 1) == 0 {
                a.remove(i);
            } else {
                let x = a[i].clone();
                a.insert(i, x);
            }
        }
        (4, Value::Array(a)) => a.clear(),
        (5, t) => {
            for _ in 0..*pick(rng, &[1, 2, 3, 20, 126, 127, 128, 200]) {
                *t = Value::Array(vec![t.take()]);
            }
        }
        (_, t) => *t = odd_value(rng),
    }
}

fn is_delim(c: u8) -> bool {
    c.is_ascii_whitespace() || b",[]{}:\"".contains(&c)
}

/// The token (a run of non-delimiters) around byte `i`.
fn token_at(b: &[u8], i: usize) -> (usize, usize) {
    let start = b[..i]
        .iter()
        .rposition(|&c| is_delim(c))
        .map_or(0, |p| p + 1);
    let end = b[i..]
        .iter()
        .position(|&c| is_delim(c))
        .map_or(b.len(), |p| i + p);
    (start, end)
}

/// The `"key": value` pair (and its comma) starting at the quote `i` when
/// one starts there: its end, scanning brackets to the value's end.
fn pair_end(b: &[u8], i: usize) -> Option<usize> {
    let close = i + 1 + b[i + 1..].iter().position(|&c| c == b'"')?;
    let colon = close
        + 1
        + b[close + 1..]
            .iter()
            .position(|&c| !c.is_ascii_whitespace())?;
    if b[colon] != b':' {
        return None;
    }
    let mut depth = 0i32;
    let mut in_str = false;
    for (k, &c) in b.iter().enumerate().skip(colon + 1) {
        match c {
            b'"' if k == 0 || b[k - 1] != b'\\' => in_str = !in_str,
            _ if in_str => {}
            b'[' | b'{' => depth += 1,
            b']' | b'}' if depth == 0 => return Some(k),
            b']' | b'}' => depth -= 1,
            b',' if depth == 0 => return Some(k + 1),
            _ => {}
        }
    }
    Some(b.len())
}

/// One change to the bytes of an input.
fn mutate_bytes(rng: &mut Rng, reader: Reader, b: &mut Vec<u8>, seeds: &[String]) {
    if b.is_empty() {
        b.extend_from_slice(pick(rng, seeds).as_bytes());
        return;
    }
    let i = rng.int(0, b.len() - 1);
    let j = (i + rng.int(1, 16)).min(b.len());
    match rng.int(0, 9) {
        0 => b[i] ^= 1 << rng.int(0, 7),
        1 => b[i] = *pick(rng, b"{}[]:,\"-+.eE0123456789 \n\\xn"),
        2 => {
            b.drain(i..j);
        }
        3 => {
            let piece = b[i..j].to_vec();
            let k = rng.int(0, b.len());
            b.splice(k..k, piece);
        }
        4 => {
            // A splice: a piece of another seed in place of a piece of this one.
            let other = pick(rng, seeds).as_bytes();
            let s = rng.int(0, other.len().saturating_sub(1));
            let e = (s + rng.int(1, 64)).min(other.len());
            b.splice(i..j, other[s..e].iter().copied());
        }
        5 | 6 => {
            let (s, e) = token_at(b, i);
            b.splice(s..e, pick(rng, &ODD_NUMBERS).bytes());
        }
        7 => b.truncate(i),
        8 if reader != Reader::Dat => {
            // Deep nesting, past serde_json's limit of 128 at times.
            let depth = *pick(rng, &[2, 64, 127, 128, 129, 1000, 20000]);
            let (open, close) = if rng.int(0, 1) == 0 {
                (b"[", b"]")
            } else {
                (b"{", b"}")
            };
            let inner = if open == b"{" {
                &b"\"a\":"[..]
            } else {
                &b""[..]
            };
            let mut nest = Vec::new();
            for _ in 0..depth {
                nest.extend_from_slice(open);
                nest.extend_from_slice(inner);
            }
            nest.push(b'1');
            nest.extend(std::iter::repeat_n(close[0], depth));
            let (s, e) = token_at(b, i);
            b.splice(s..e, nest);
        }
        8 => {
            // A count in the header made huge or odd.
            let k = rng.int(0, 4);
            let starts: Vec<usize> = (0..b.len())
                .filter(|&p| !is_delim(b[p]) && (p == 0 || is_delim(b[p - 1])))
                .collect();
            if let Some(&p) = starts.get(k) {
                let (s, e) = token_at(b, p);
                b.splice(
                    s..e,
                    pick(rng, &["10000", "9999", "3333", "0", "1", "2", "4"]).bytes(),
                );
            }
        }
        _ => {
            // A key (any string followed by `:`) misspelt, deleted or given twice.
            let Some(q) = b[i..].iter().position(|&c| c == b'"').map(|p| i + p) else {
                return;
            };
            let Some(end) = pair_end(b, q) else {
                return;
            };
            match rng.int(0, 2) {
                0 => {
                    b.drain(q..end);
                }
                1 => {
                    let mut pair = b[q..end].to_vec();
                    if pair.last() != Some(&b',') {
                        pair.push(b',');
                    }
                    b.splice(q..q, pair);
                }
                _ => {
                    let close = q + 1 + b[q + 1..].iter().position(|&c| c == b'"').unwrap_or(0);
                    let key = String::from_utf8_lossy(&b[q + 1..close]).into_owned();
                    b.splice(q + 1..close, misspelt(rng, &key).into_bytes());
                }
            }
        }
    }
}

/// A reader's seeds: the files of `corpus/<reader>/`, and for `.dat` the
/// `.dat` files of at most 8 KiB in the folders `dat_dirs` (the Siconos
/// conformance data: read at run time, never copied into the project).
pub fn seeds(reader: Reader, corpus: &Path, dat_dirs: &[std::path::PathBuf]) -> Vec<String> {
    let mut dirs = vec![corpus.join(reader.name())];
    if reader == Reader::Dat {
        dirs.extend_from_slice(dat_dirs);
    }
    let mut out = Vec::new();
    for dir in dirs {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        let mut files: Vec<_> = entries.filter_map(|e| Some(e.ok()?.path())).collect();
        files.sort();
        for f in files {
            let dat = f.extension().is_some_and(|e| e == "dat");
            let small = f.metadata().is_ok_and(|m| m.len() <= 8192);
            if (reader != Reader::Dat || dat) && small {
                if let Ok(text) = std::fs::read_to_string(&f) {
                    out.push(text);
                }
            }
        }
    }
    out
}

/// What a run found.
#[derive(Default)]
pub struct Tally {
    /// Inputs read.
    pub execs: u64,
    /// Of which accepted.
    pub accepted: u64,
    /// Inputs that panicked the reader, took over [`HANG`], or were
    /// judged wrong by [`check`]: (reader, what, the input).
    pub faults: Vec<(Reader, String, String)>,
    /// The slowest input: its time, reader and text.
    pub slowest: (Duration, Option<Reader>, String),
}

/// An input read for longer than this is a fault.
pub const HANG: Duration = Duration::from_secs(1);

thread_local! {
    /// Set while this thread reads an input: the panic hook then keeps
    /// the message here instead of printing it.
    static PANIC: std::cell::RefCell<Option<Option<String>>> = const { std::cell::RefCell::new(None) };
}

/// Installs (once) a panic hook that keeps the message of a panic inside
/// [`run`] for its tally and leaves any other panic to the previous hook.
fn install_hook() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            let kept = PANIC.with(|p| match &mut *p.borrow_mut() {
                Some(slot) => {
                    *slot = Some(info.to_string());
                    true
                }
                None => false,
            });
            if !kept {
                previous(info);
            }
        }));
    });
}

/// Reads `execs` inputs, the seeds first and then ones made by [`mutate`]
/// with `seed`, catching panics, timing each, and adds what it found to
/// `tally`.
pub fn run(reader: Reader, seeds: &[String], execs: u64, seed: u64, tally: &mut Tally) {
    assert!(
        !seeds.is_empty(),
        "no seeds for the {} reader",
        reader.name()
    );
    install_hook();
    let mut rng = Rng::new(seed);
    for k in 0..execs {
        let text = match seeds.get(k as usize) {
            Some(s) => s.clone(),
            None => mutate(&mut rng, reader, seeds),
        };
        PANIC.with(|p| *p.borrow_mut() = Some(None));
        let start = Instant::now();
        let verdict = std::panic::catch_unwind(|| check(reader, &text));
        let took = start.elapsed();
        let panic = PANIC.with(|p| p.borrow_mut().take().flatten());
        tally.execs += 1;
        let fault = match verdict {
            Ok(Ok(accepted)) => {
                tally.accepted += u64::from(accepted);
                None
            }
            Ok(Err(why)) => Some(why),
            Err(_) => Some(format!("panic: {}", panic.unwrap_or_default())),
        };
        if took > tally.slowest.0 {
            tally.slowest = (took, Some(reader), text.clone());
        }
        if let Some(why) = fault.or_else(|| (took > HANG).then(|| format!("took {took:?}"))) {
            tally.faults.push((reader, why, text));
        }
    }
}

/// One libFuzzer input (fuzz/fuzz_targets/): a fault found by [`check`]
/// panics, which libFuzzer reports with the input.
pub fn fuzz(reader: Reader, data: &[u8]) {
    if let Err(why) = check(reader, &String::from_utf8_lossy(data)) {
        panic!("{} reader: {why}", reader.name());
    }
}
