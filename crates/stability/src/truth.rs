//! Ground truth known by construction, and its JSON sidecar.
//!
//! Every generated scene comes with a [`Truth`]: whether the pair is
//! collision free, the state sequence of its timeline, and each isolated
//! contact instant as an exact [`Surd`]. None of it is computed by the
//! engine: it comes from a *level function* `φ(u)` of the construction,
//! rational in `u`, with `φ > 0` exactly where the bodies are separate,
//! `φ = 0` where they touch and `φ < 0` where they overlap, whose roots are
//! known in closed form (see [`crate::families`]).

use crate::{StabilityError, Surd};
use ccd_arith::Rat;
use ccd_exact::State;
use serde_json::{json, Map, Value};

/// The instant of closest approach of a grazing pass and the signed gap
/// there (positive: the bodies miss by that much; zero: they touch; negative:
/// they overlap by that much).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Closest {
    /// The instant (a time in the span).
    pub t: Rat,
    /// The signed Euclidean gap at that instant.
    pub gap: Rat,
}

/// Where a true isolated contact is, as far as the construction knows it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Instant {
    /// Exactly here (a closed form).
    At(Surd),
    /// The only contact in the closed interval `[lo, hi]` — for
    /// constructions whose instants have no closed form (non-homothetic
    /// grazes, perturbed benchmark scenes), where the construction proves a
    /// bracket instead (see [`crate::families::graze`]).
    Within(Rat, Rat),
}

impl Instant {
    /// The instant's form, for messages and comments.
    pub fn describe(&self) -> String {
        match self {
            Instant::At(s) => s.describe(),
            Instant::Within(lo, hi) => format!("within [{lo}, {hi}]"),
        }
    }

    /// A rational inside the truth: the value to `2^-bits`, or the
    /// bracket's midpoint.
    pub fn approx(&self, bits: u64) -> Rat {
        match self {
            Instant::At(s) => s.approx(bits),
            Instant::Within(lo, hi) => Rat::midpoint(lo, hi),
        }
    }

    /// The lower and upper ends of what is known (equal up to `2^-bits`
    /// for a closed form).
    pub fn bounds(&self, bits: u64) -> (Rat, Rat) {
        match self {
            Instant::At(s) => (s.approx(bits), s.approx(bits)),
            Instant::Within(lo, hi) => (lo.clone(), hi.clone()),
        }
    }

    /// `|x − instant|` (a closed form, to about `2^-200`), or the distance
    /// from `x` to the bracket — a lower bound of the true error, 0 inside.
    pub fn distance(&self, x: &Rat) -> f64 {
        match self {
            Instant::At(s) => s.distance(x),
            Instant::Within(lo, hi) if x < lo => (lo - x).to_f64(),
            Instant::Within(_, hi) if x > hi => (x - hi).to_f64(),
            Instant::Within(..) => 0.0,
        }
    }

    /// The reported enclosure `[lo, hi]` is consistent with the truth,
    /// decided exactly: it contains the closed form, or it meets the
    /// bracket (the most a bracket can prove).
    pub fn agrees(&self, lo: &Rat, hi: &Rat) -> bool {
        match self {
            Instant::At(s) => s.within(lo, hi),
            Instant::Within(a, b) => lo <= b && a <= hi,
        }
    }

    /// The image `t0 + h·self` under `t = t0 + u·h`, `h > 0`.
    pub fn affine(&self, t0: &Rat, h: &Rat) -> Instant {
        match self {
            Instant::At(s) => Instant::At(s.affine(t0, h)),
            Instant::Within(lo, hi) => Instant::Within(t0 + &(h * lo), t0 + &(h * hi)),
        }
    }

    /// The closed form, when there is one.
    pub fn exact(&self) -> Option<&Surd> {
        match self {
            Instant::At(s) => Some(s),
            Instant::Within(..) => None,
        }
    }
}

/// What a scene's answer must be.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Truth {
    /// The family the scene belongs to.
    pub family: String,
    /// The case within the family (human-readable).
    pub case: String,
    /// The family's parameter, e.g. `k` for a gap of `10⁻ᵏ`.
    pub k: Option<u32>,
    /// `true` exactly when the bodies are separate throughout the span.
    pub collision_free: bool,
    /// The timeline's states in order; an isolated contact is a `Touch`
    /// between two pieces (or at an end).
    pub states: Vec<State>,
    /// The isolated contact instants (times), in increasing order.
    pub contacts: Vec<Instant>,
    /// For grazing passes: the closest approach.
    pub closest: Option<Closest>,
}

/// The sign of a level function as a state: `φ > 0` separate, `= 0` touch,
/// `< 0` overlap.
pub fn state_of_level(phi: &Rat) -> State {
    match phi.signum() {
        1 => State::Separate,
        0 => State::Touch,
        _ => State::Overlap,
    }
}

/// The state with the contract's name `name`.
pub fn parse_state(name: &str) -> Option<State> {
    [State::Separate, State::Touch, State::Overlap]
        .into_iter()
        .find(|s| s.name() == name)
}

/// The timeline's state sequence on `u ∈ [0, 1]` given the level function
/// `phi` and its roots `contacts` (increasing, in `[0, 1]`): a `Touch` at each
/// root and, on each open piece between consecutive roots and ends, the
/// state of `φ` at a rational strictly inside it; equal neighbours merge (so
/// `φ ≡ 0` gives `[Touch]`).
pub fn states_from_level(
    contacts: &[Surd],
    phi: &dyn Fn(&Rat) -> Rat,
) -> Result<Vec<State>, StabilityError> {
    for (i, c) in contacts.iter().enumerate() {
        let before = contacts.get(i.wrapping_sub(1));
        if c.cmp_rat(&Rat::zero()).is_lt()
            || c.cmp_rat(&Rat::one()).is_gt()
            || before.is_some_and(|b| b.approx(200) >= c.approx(200))
        {
            return Err(StabilityError::Truth(format!(
                "contact {} outside [0, 1] or out of order",
                c.describe()
            )));
        }
    }
    // Bounds of the pieces: the ends (unless a contact is there) and the
    // contacts, each flagged "is a contact".
    let mut bounds: Vec<(Surd, bool)> = Vec::new();
    if contacts
        .first()
        .is_none_or(|c| !c.cmp_rat(&Rat::zero()).is_eq())
    {
        bounds.push((Surd::rational(Rat::zero()), false));
    }
    bounds.extend(contacts.iter().map(|c| (c.clone(), true)));
    if contacts
        .last()
        .is_none_or(|c| !c.cmp_rat(&Rat::one()).is_eq())
    {
        bounds.push((Surd::rational(Rat::one()), false));
    }
    let mut states = Vec::new();
    if bounds[0].1 {
        states.push(State::Touch);
    }
    for w in bounds.windows(2) {
        let mid = Rat::midpoint(&w[0].0.approx(200), &w[1].0.approx(200));
        if !(w[0].0.cmp_rat(&mid).is_lt() && w[1].0.cmp_rat(&mid).is_gt()) {
            return Err(StabilityError::Truth(format!(
                "no rational sample between {} and {}",
                w[0].0.describe(),
                w[1].0.describe()
            )));
        }
        states.push(state_of_level(&phi(&mid)));
        if w[1].1 {
            states.push(State::Touch);
        }
    }
    states.dedup();
    Ok(states)
}

impl Truth {
    /// The truth of a construction on the span `[t0, t1]` with level
    /// function `phi(u)` (in `u = (t − t0)/(t1 − t0)`) and its roots
    /// `contacts_u` in `[0, 1]`, increasing.
    pub fn from_level(
        family: &str,
        case: String,
        k: Option<u32>,
        span: &[Rat; 2],
        contacts_u: Vec<Surd>,
        phi: &dyn Fn(&Rat) -> Rat,
    ) -> Result<Truth, StabilityError> {
        let states = states_from_level(&contacts_u, phi)?;
        let h = &span[1] - &span[0];
        Ok(Truth {
            family: family.to_string(),
            case,
            k,
            collision_free: states == [State::Separate],
            states,
            contacts: contacts_u
                .iter()
                .map(|c| Instant::At(c.affine(&span[0], &h)))
                .collect(),
            closest: None,
        })
    }

    /// The truth of a construction that proves the state sequence `states`
    /// and, for each isolated contact, a bracket or closed form
    /// `contacts_u` in `u ∈ [0, 1]` (increasing, disjoint) on `span`.
    pub fn known(
        family: &str,
        case: String,
        k: Option<u32>,
        span: &[Rat; 2],
        contacts_u: Vec<Instant>,
        states: Vec<State>,
    ) -> Result<Truth, StabilityError> {
        let touches = states.iter().filter(|s| **s == State::Touch).count();
        let ordered = contacts_u.windows(2).all(|w| {
            let (_, hi) = w[0].bounds(200);
            let (lo, _) = w[1].bounds(200);
            hi <= lo
        });
        let inside = contacts_u.iter().all(|c| {
            let (lo, hi) = c.bounds(200);
            lo >= Rat::zero() && hi <= Rat::one() && lo <= hi
        });
        if touches != contacts_u.len() || !ordered || !inside {
            return Err(StabilityError::Truth(format!(
                "{family}-{case}: contacts and states disagree or out of order"
            )));
        }
        let h = &span[1] - &span[0];
        Ok(Truth {
            family: family.to_string(),
            case,
            k,
            collision_free: states == [State::Separate],
            states,
            contacts: contacts_u.iter().map(|c| c.affine(&span[0], &h)).collect(),
            closest: None,
        })
    }

    /// One state throughout the span and no isolated contact.
    pub fn throughout(family: &str, case: String, state: State) -> Truth {
        Truth {
            family: family.to_string(),
            case,
            k: None,
            collision_free: state == State::Separate,
            states: vec![state],
            contacts: Vec::new(),
            closest: None,
        }
    }

    /// The sidecar JSON.
    pub fn to_json(&self) -> Value {
        let surd = |c: &Instant| match c {
            Instant::At(s) => json!({"a": s.a.to_string(), "b": s.b.to_string(),
                   "q": s.q.to_string(), "closed_form": s.describe(),
                   "approx": s.approx(200).to_decimal(40)}),
            Instant::Within(lo, hi) => json!({"within": [lo.to_string(), hi.to_string()],
                   "approx": Rat::midpoint(lo, hi).to_decimal(40)}),
        };
        let mut m = Map::new();
        m.insert("family".into(), json!(self.family));
        m.insert("case".into(), json!(self.case));
        m.insert("k".into(), json!(self.k));
        m.insert("collision_free".into(), json!(self.collision_free));
        m.insert(
            "states".into(),
            json!(self.states.iter().map(|s| s.name()).collect::<Vec<_>>()),
        );
        m.insert(
            "contacts".into(),
            Value::Array(self.contacts.iter().map(surd).collect()),
        );
        if let Some(c) = &self.closest {
            m.insert(
                "closest".into(),
                json!({"t": c.t.to_string(), "gap": c.gap.to_string()}),
            );
        }
        Value::Object(m)
    }

    /// Reads a sidecar written by [`Truth::to_json`]; `name` is for messages.
    pub fn from_json(name: &str, text: &str) -> Result<Truth, StabilityError> {
        let bad = |reason: String| StabilityError::TruthFile {
            name: name.to_string(),
            reason,
        };
        let v: Value = serde_json::from_str(text).map_err(|e| bad(e.to_string()))?;
        let str_of = |v: &Value, key: &str| -> Result<String, StabilityError> {
            v.get(key)
                .and_then(Value::as_str)
                .map(str::to_string)
                .ok_or_else(|| bad(format!("missing string `{key}`")))
        };
        let rat_of = |v: &Value, key: &str| -> Result<Rat, StabilityError> {
            let s = str_of(v, key)?;
            Rat::parse_exact(&s).map_err(|e| bad(format!("`{key}` = {s:?}: {e}")))
        };
        let collision_free = v
            .get("collision_free")
            .and_then(Value::as_bool)
            .ok_or_else(|| bad("missing bool `collision_free`".into()))?;
        let k = match v.get("k") {
            None | Some(Value::Null) => None,
            Some(x) => Some(
                x.as_u64()
                    .and_then(|k| u32::try_from(k).ok())
                    .ok_or_else(|| bad("`k` is not a small integer".into()))?,
            ),
        };
        let states = v
            .get("states")
            .and_then(Value::as_array)
            .ok_or_else(|| bad("missing array `states`".into()))?
            .iter()
            .map(|s| {
                s.as_str()
                    .and_then(parse_state)
                    .ok_or_else(|| bad(format!("unknown state {s}")))
            })
            .collect::<Result<Vec<_>, _>>()?;
        let contacts = v
            .get("contacts")
            .and_then(Value::as_array)
            .ok_or_else(|| bad("missing array `contacts`".into()))?
            .iter()
            .map(|c| match c.get("within").and_then(Value::as_array) {
                Some(w) if w.len() == 2 => {
                    let end = |i: usize| {
                        let s = w[i]
                            .as_str()
                            .ok_or_else(|| bad("`within` holds strings".into()))?;
                        Rat::parse_exact(s).map_err(|e| bad(format!("`within` = {s:?}: {e}")))
                    };
                    Ok(Instant::Within(end(0)?, end(1)?))
                }
                Some(_) => Err(bad("`within` is not a pair".into())),
                None => Ok(Instant::At(Surd::new(
                    rat_of(c, "a")?,
                    rat_of(c, "b")?,
                    rat_of(c, "q")?,
                )?)),
            })
            .collect::<Result<Vec<_>, _>>()?;
        let closest = match v.get("closest") {
            None | Some(Value::Null) => None,
            Some(c) => Some(Closest {
                t: rat_of(c, "t")?,
                gap: rat_of(c, "gap")?,
            }),
        };
        Ok(Truth {
            family: str_of(&v, "family")?,
            case: str_of(&v, "case")?,
            k,
            collision_free,
            states,
            contacts,
            closest,
        })
    }
}
