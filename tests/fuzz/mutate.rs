//! The mutator: a shipped scene → a mutant scene text, by one to three
//! operators on the TOML document (numbers, arrays, tables) and, now and
//! then, garbage at the text level.
//!
//! Number operators produce what made the exact path stall in issue 12:
//! decimals with 5 to 300 digits close to the original value, long random
//! fractions, exponents `1e±40`, `1e±300`, `1e±1000` and at the limit
//! `1e±4096` (and just beyond it), big ratios `p/q`, small integers
//! (zero and negative radii and weights) and sign flips. Structural
//! operators drop or duplicate control points and array entries, empty or
//! nest arrays, delete keys, add unknown keys (some longer than any message
//! should echo) and known keys in the wrong place, swap motion kinds and put
//! values of the wrong type.

use crate::rng::Rng;
use toml_edit::{Array, DocumentMut, Item, TableLike, Value};

/// What an operator acts on.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Class {
    /// A table (`[header]`, inline or the root).
    Table,
    /// An array.
    Array,
    /// A number, or a string that reads as one.
    Number,
    /// A motion kind string.
    Kind,
    /// Any value that is not a container.
    Leaf,
}

/// A node of the document, borrowed for one operator.
enum Node<'a> {
    Table(&'a mut dyn TableLike),
    Array(&'a mut Array),
    Leaf(&'a mut Value),
}

/// The document-level operators, with their weights.
pub const OPERATORS: [(&str, u32); 15] = [
    ("long-decimal", 15),
    ("long-fraction", 8),
    ("exponent", 10),
    ("big-ratio", 8),
    ("small-int", 7),
    ("sign-flip", 7),
    ("wrong-type", 4),
    ("kind-swap", 4),
    ("drop-element", 6),
    ("duplicate-element", 6),
    ("clear-array", 2),
    ("nest-element", 2),
    ("delete-key", 5),
    ("unknown-key", 4),
    ("known-key", 5),
];

/// The text-level operator (applied to one mutant in eight).
pub const GARBAGE: &str = "garbage";

/// A mutant and the operators that made it.
pub struct Mutant {
    /// The scene text.
    pub text: String,
    /// The operators applied, in order (those that found no target omitted).
    pub ops: Vec<&'static str>,
}

/// Digit counts of the long numbers: around the old stall threshold (about
/// 23 digits) and well beyond.
const LONG: [usize; 7] = [5, 20, 23, 30, 60, 100, 300];

const KINDS: [&str; 5] = ["static", "translation", "rigid", "affine", "helical"];

/// Values for keys added or replaced: of each shape the format uses.
const TEMPLATES: [&str; 13] = [
    "[1, 2, 3]",
    "[[1, 0, 0, 0], [0, 1, 0, 0]]",
    "[1, 1]",
    "[\"1/2\", 2]",
    "\"rigid\"",
    "\"translation\"",
    "1",
    "0",
    "[[0, 0, 0], [1, 1, 1], [2, 0, 1]]",
    "{ kind = \"static\" }",
    "[0, 1]",
    "[[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]]",
    "[[\"-1\", 0, 0], [\"1e-30\", 0, 0]]",
];

const KNOWN_KEYS: [&str; 14] = [
    "radii",
    "motion",
    "kind",
    "center",
    "orientation",
    "weights",
    "matrix",
    "axis",
    "rate",
    "span",
    "format",
    "frequency",
    "base",
    "velocity",
];

const WRONG: [&str; 10] = [
    "true",
    "\"abc\"",
    "[]",
    "{}",
    "1979-05-27",
    "\"\"",
    "nan",
    "inf",
    "\"1/0\"",
    "[1, [2]]",
];

/// Mutates `seed` (a valid scene) with the generator `rng`.
pub fn mutate(seed: &str, rng: &mut Rng) -> Mutant {
    let mut doc: DocumentMut = seed.parse().expect("a shipped scene is TOML");
    let mut raw = Vec::new();
    let mut ops = Vec::new();
    for _ in 0..1 + rng.below(3) {
        let op = weighted(rng);
        if apply(&mut doc, op, rng, &mut raw) {
            ops.push(op);
        }
    }
    let mut text = doc.to_string();
    // Raw texts stand in the document as placeholder strings until here, so
    // they may be anything (bare numbers beyond binary64, dates, garbage).
    for (k, r) in raw.iter().enumerate() {
        text = text.replace(&format!("\"{}\"", placeholder(k)), r);
    }
    if rng.chance(1, 8) {
        text = garbage(&text, rng);
        ops.push(GARBAGE);
    }
    Mutant { text, ops }
}

fn placeholder(k: usize) -> String {
    format!("@@fuzz-raw-{k}@@")
}

fn weighted(rng: &mut Rng) -> &'static str {
    let total: u32 = OPERATORS.iter().map(|(_, w)| w).sum();
    let mut x = rng.below(total as usize) as u32;
    for (name, w) in OPERATORS {
        if x < w {
            return name;
        }
        x -= w;
    }
    unreachable!("weights sum to total")
}

/// The class an operator acts on.
fn class_of(op: &str) -> Class {
    match op {
        "long-decimal" | "long-fraction" | "exponent" | "big-ratio" | "small-int" | "sign-flip" => {
            Class::Number
        }
        "wrong-type" => Class::Leaf,
        "kind-swap" => Class::Kind,
        "drop-element" | "duplicate-element" | "clear-array" | "nest-element" => Class::Array,
        _ => Class::Table,
    }
}

/// The text of a number leaf (`None` for other leaves) and whether it is a
/// bare TOML number rather than a string.
fn number_text(v: &Value) -> Option<(String, bool)> {
    match v {
        Value::Integer(i) => Some((i.display_repr().into_owned(), true)),
        Value::Float(f) => Some((f.display_repr().into_owned(), true)),
        Value::String(s) => {
            let t = s.value();
            let numeric = t.starts_with(|c: char| c.is_ascii_digit() || "+-.".contains(c));
            numeric.then(|| (t.clone(), false))
        }
        _ => None,
    }
}

fn is_kind(v: &Value) -> bool {
    matches!(v, Value::String(s) if KINDS.contains(&s.value().as_str()))
}

fn matches(node: &Node<'_>, class: Class) -> bool {
    match (node, class) {
        (Node::Table(_), Class::Table) => true,
        (Node::Array(_), Class::Array) => true,
        (Node::Leaf(v), Class::Number) => number_text(v).is_some(),
        (Node::Leaf(v), Class::Kind) => is_kind(v),
        (Node::Leaf(_), Class::Leaf) => true,
        _ => false,
    }
}

/// Calls `f` on every node in document order until it returns true.
fn walk_table(t: &mut dyn TableLike, f: &mut dyn FnMut(Node<'_>) -> bool) -> bool {
    if f(Node::Table(&mut *t)) {
        return true;
    }
    t.iter_mut().any(|(_, item)| walk_item(item, f))
}

fn walk_item(item: &mut Item, f: &mut dyn FnMut(Node<'_>) -> bool) -> bool {
    match item {
        Item::Table(t) => walk_table(t, f),
        Item::Value(v) => walk_value(v, f),
        Item::ArrayOfTables(a) => a.iter_mut().any(|t| walk_table(t, f)),
        Item::None => false,
    }
}

fn walk_value(v: &mut Value, f: &mut dyn FnMut(Node<'_>) -> bool) -> bool {
    match v {
        Value::Array(a) => {
            if f(Node::Array(&mut *a)) {
                return true;
            }
            a.iter_mut().any(|x| walk_value(x, f))
        }
        Value::InlineTable(t) => walk_table(t, f),
        leaf => f(Node::Leaf(leaf)),
    }
}

/// Applies `op` to a random node of its class; false when there is none.
fn apply(doc: &mut DocumentMut, op: &'static str, rng: &mut Rng, raw: &mut Vec<String>) -> bool {
    let class = class_of(op);
    let mut count = 0;
    walk_table(doc.as_table_mut(), &mut |n| {
        count += matches(&n, class) as usize;
        false
    });
    if count == 0 {
        return false;
    }
    let target = rng.below(count);
    let mut seen = 0;
    let mut done = false;
    walk_table(doc.as_table_mut(), &mut |n| {
        if !matches(&n, class) {
            return false;
        }
        seen += 1;
        if seen <= target {
            return false;
        }
        done = act(n, op, rng, raw);
        true
    });
    done
}

/// A value that the final text shows as `text`, verbatim.
fn raw_value(text: String, raw: &mut Vec<String>) -> Value {
    raw.push(text);
    Value::from(placeholder(raw.len() - 1))
}

fn act(node: Node<'_>, op: &str, rng: &mut Rng, raw: &mut Vec<String>) -> bool {
    match node {
        Node::Leaf(v) => {
            let new = match op {
                "wrong-type" => rng.pick(&WRONG).to_string(),
                "kind-swap" => {
                    let others = [
                        "static",
                        "translation",
                        "rigid",
                        "affine",
                        "helical",
                        "spin",
                    ];
                    format!("\"{}\"", rng.pick(&others))
                }
                _ => {
                    let (text, bare) = number_text(v).expect("a number leaf");
                    number(op, &text, bare, rng)
                }
            };
            let decor = v.decor().clone();
            *v = raw_value(new, raw);
            *v.decor_mut() = decor;
            true
        }
        Node::Array(a) => {
            if a.is_empty() && op != "clear-array" {
                return false;
            }
            match op {
                "drop-element" => {
                    a.remove(rng.below(a.len()));
                }
                "duplicate-element" => {
                    let i = rng.below(a.len());
                    let copy = a.get(i).expect("in range").clone();
                    a.insert_formatted(i, copy);
                }
                "clear-array" => a.clear(),
                _ => {
                    let i = rng.below(a.len());
                    let inner = a.remove(i);
                    let mut wrapped = Array::new();
                    wrapped.push_formatted(inner);
                    a.insert(i, wrapped);
                }
            }
            true
        }
        Node::Table(t) => match op {
            "delete-key" => {
                let keys: Vec<String> = t.iter().map(|(k, _)| k.to_string()).collect();
                if keys.is_empty() {
                    return false;
                }
                let key = rng.pick(&keys).clone();
                t.remove(&key);
                true
            }
            "unknown-key" => {
                let key = match rng.below(4) {
                    0 => rng
                        .pick(&["extra", "Radii", "weight", "centre"])
                        .to_string(),
                    1 => "two words".to_string(),
                    _ => "x".repeat(65 + rng.below(400)),
                };
                t.insert(&key, Item::Value(raw_value("1".into(), raw)));
                true
            }
            _ => {
                let key = rng.pick(&KNOWN_KEYS);
                let value = raw_value(rng.pick(&TEMPLATES).to_string(), raw);
                t.insert(key, Item::Value(value));
                true
            }
        },
    }
}

/// The replacement text of number `text` (a bare TOML number when `bare`)
/// under number operator `op`.
fn number(op: &str, text: &str, bare: bool, rng: &mut Rng) -> String {
    let neg = text.starts_with('-');
    let sign = if neg { "-" } else { "" };
    let new = match op {
        "long-decimal" => {
            let zeros = "0".repeat(*rng.pick(&LONG));
            let plain = text.trim_start_matches(['+', '-']);
            if !plain.is_empty() && plain.bytes().all(|b| b.is_ascii_digit() || b == b'.') {
                let dot = if plain.contains('.') { "" } else { "." };
                format!("{sign}{plain}{dot}{zeros}1")
            } else {
                format!("{sign}1.{zeros}1")
            }
        }
        "long-fraction" => {
            let n = *rng.pick(&LONG);
            format!("{sign}0.{}", rng.digits(n, false))
        }
        "exponent" => {
            let e = if rng.chance(1, 6) {
                *rng.pick(&["4096", "-4096", "4097", "-4097", "8192"])
            } else {
                *rng.pick(&["40", "-40", "300", "-300", "1000", "-1000"])
            };
            format!("{sign}1e{e}")
        }
        "big-ratio" => {
            let (p, q) = (1 + rng.below(40), 1 + rng.below(40));
            format!("{sign}{}/{}", rng.digits(p, true), rng.digits(q, true))
        }
        "small-int" => return rng.range(-10, 10).to_string(),
        _ => match text.strip_prefix('-') {
            Some(rest) => rest.to_string(),
            None => format!("-{}", text.trim_start_matches('+')),
        },
    };
    // A flipped number keeps its form; a new one is bare one time in four
    // where TOML can write it (not a fraction; `1e1000` bare is not TOML,
    // which is a case too), otherwise a string.
    if op == "sign-flip" && bare || !new.contains('/') && rng.chance(1, 4) {
        new
    } else {
        format!("\"{new}\"")
    }
}

/// One text-level edit: insert junk, delete a run, repeat a line or cut
/// the text short.
fn garbage(text: &str, rng: &mut Rng) -> String {
    let mut chars: Vec<char> = text.chars().collect();
    let at = rng.below(chars.len() + 1);
    match rng.below(4) {
        0 => {
            const JUNK: &[char] = &[
                '[', ']', '{', '}', '=', ',', '.', '"', '\'', '#', '\n', ' ', '0', '1', '9', '-',
                '+', '_', '/', 'e', 'E', 'i', 'n', 'f', 'a', 'é', '\u{0}', '\u{7f}', '\t', '\\',
            ];
            let junk: Vec<char> = (0..1 + rng.below(20)).map(|_| *rng.pick(JUNK)).collect();
            chars.splice(at..at, junk);
        }
        1 => {
            let end = (at + 1 + rng.below(40)).min(chars.len());
            chars.drain(at..end);
        }
        2 => {
            let text: String = chars.iter().collect();
            let lines: Vec<&str> = text.split_inclusive('\n').collect();
            let i = rng.below(lines.len());
            let mut out: Vec<&str> = lines.clone();
            out.insert(i, lines[i]);
            return out.concat();
        }
        _ => chars.truncate(at),
    }
    chars.into_iter().collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    const SEED: &str = "span = [0, 1]\n[a]\nradii = [2, \"1/2\", 1.5]\n[b]\nradii = [1, 1, 1]\n[b.motion]\nkind = \"translation\"\ncenter = [[-6, 1, 0], [6, \"1.25\", 0]]\n";

    #[test]
    fn every_operator_fires_and_mutants_differ() {
        let mut seen: Vec<&str> = Vec::new();
        let mut changed = 0;
        let mut parsed = 0;
        for case in 0..600 {
            let m = mutate(SEED, &mut Rng::for_case(5, case));
            changed += (m.text != SEED) as usize;
            parsed += m.text.parse::<DocumentMut>().is_ok() as usize;
            assert!(!m.text.contains("@@fuzz-raw"), "{}", m.text);
            seen.extend(&m.ops);
        }
        for (op, _) in OPERATORS {
            assert!(seen.contains(&op), "{op} never applied");
        }
        assert!(seen.contains(&GARBAGE));
        assert!(
            changed > 550,
            "{changed} of 600 mutants differ from the seed"
        );
        // Most mutants stay TOML, so the checks get past the TOML parser.
        assert!(parsed > 400, "{parsed} of 600 mutants are TOML");
    }

    #[test]
    fn a_seed_gives_the_same_mutant() {
        for case in 0..20 {
            let a = mutate(SEED, &mut Rng::for_case(9, case));
            let b = mutate(SEED, &mut Rng::for_case(9, case));
            assert_eq!(a.text, b.text);
        }
    }

    #[test]
    fn long_decimals_stay_near_the_original() {
        let mut rng = Rng::for_case(1, 1);
        let t = number("long-decimal", "1.25", false, &mut rng);
        assert!(t.starts_with("\"1.250") && t.ends_with("1\""), "{t}");
        let t = number("long-decimal", "-6", true, &mut rng);
        let t = t.trim_matches('"');
        assert!(t.starts_with("-6.0") && t.ends_with('1'), "{t}");
        assert_eq!(number("sign-flip", "-6", true, &mut rng), "6");
        assert_eq!(number("sign-flip", "1/2", false, &mut rng), "\"-1/2\"");
    }
}
