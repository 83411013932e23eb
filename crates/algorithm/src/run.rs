//! Algorithm 1 (Section 5): the branches of Theorems 5.2 and 5.4–5.6, the
//! touch test of Theorem 3.10(2) at each candidate, and the walk over the
//! candidates.

use crate::assemble::{assemble, Break, Walk};
use crate::decide::possible_with;
use crate::oracle::{At, Decided, Found, Oracle, Vanishing};
use crate::{CcdError, Item, Options};
use ccd_arith::Rat;
use ccd_classify::Configuration;
use ccd_subres::Quantity;
use ccd_timeline::{Branch, Gap, Instant, Outcome, State, Stats};

/// A cluster wider than `2^−16` of the span is reported as an undecided gap
/// (its roots were not separated), a narrower one as one uncertified
/// contact candidate.
const CLUSTER_GAP_LOG2: i64 = -16;

/// The configuration at the rational parameter `x` (Theorem 3.10), through
/// the oracle's levels; a guess marked uncertified when none decides.
pub fn state_at<O: Oracle>(o: &O, x: &Rat) -> Decided {
    for level in 0..O::LEVELS {
        let p = possible_with(&mut *o.signs(At::Sample(x), level), &[], false);
        if let Some(c) = p.single() {
            return Decided {
                state: State::from(c),
                certified: true,
            };
        }
    }
    Decided {
        state: o.guess(x),
        certified: false,
    }
}

/// Theorem 3.10(2) at the candidate `r`, a root of the quantities `zeros`:
/// which configurations its signs allow, through the oracle's levels until
/// a touch is ruled out or decided.
fn touch_at<O: Oracle>(o: &O, r: &mut O::Root, zeros: &[Quantity]) -> crate::Possible {
    let mut p = crate::Possible::default();
    for level in 0..O::LEVELS {
        p = possible_with(&mut *o.signs(At::Root(r), level), zeros, true);
        if !p.touch || p.single().is_some() {
            break;
        }
    }
    p
}

/// Where the contact candidates come from.
enum Plan {
    /// The roots of `q`, at which the quantities `zeros` vanish.
    Roots(Quantity, &'static [Quantity]),
    /// One state on the whole span (Theorems 5.5, 5.6), the quantities
    /// vanishing identically.
    Throughout(Decided, &'static [Quantity]),
    /// The whole span undecided, and why.
    Undecided(&'static str),
}

/// Algorithm 1's branches (Theorems 5.2, 5.4–5.6).
fn plan<O: Oracle>(o: &mut O, state0: Decided, stats: &mut Stats) -> Plan {
    let (branch, plan) = match o.vanishes(Quantity::Sr0) {
        Vanishing::Not(_) => (Branch::Sr0, Plan::Roots(Quantity::Sr0, &[Quantity::Sr0])),
        Vanishing::Unknown => (
            Branch::Sr0Undecided,
            Plan::Undecided("sr0 neither proven nonzero at a sample nor identically zero"),
        ),
        Vanishing::Identically => match o.vanishes(Quantity::Sr11) {
            // Theorem 5.5: touching at one non-root of sr11 means touching
            // throughout; otherwise the contacts are among its roots (5.4).
            Vanishing::Not(delta) => {
                let at = delta.map(|d| state_at(o, &d));
                let plan = match at {
                    Some(d) if d.state == State::Touch => Plan::Throughout(d, &[Quantity::Sr0]),
                    _ => Plan::Roots(Quantity::Sr11, &[Quantity::Sr0, Quantity::Sr11]),
                };
                (Branch::Sr11, plan)
            }
            // Theorem 5.6: the state at t0 holds throughout.
            Vanishing::Identically => (
                Branch::Throughout,
                Plan::Throughout(state0, &[Quantity::Sr0, Quantity::Sr11]),
            ),
            Vanishing::Unknown => (
                Branch::Sr11Undecided,
                Plan::Undecided("sr11 neither proven nonzero at a sample nor identically zero"),
            ),
        },
    };
    stats.branch = Some(branch);
    plan
}

/// The contact candidates of `q` walked in order: each root decided by
/// Theorem 3.10(2) and, when a touch, refined; clusters subdivided or
/// reported; gaps kept (adjacent ones merged); everything clipped to the
/// domain. Stops after the first break with `first_contact_only`. `None`
/// when the attempt gave up.
fn walk_candidates<O: Oracle>(
    o: &O,
    q: Quantity,
    zeros: &[Quantity],
    roots: impl Iterator<Item = Found<O::Root>>,
    opts: &Options,
    stats: &mut Stats,
) -> Result<Option<Walk<O::Root>>, CcdError> {
    let mut out = Walk::default();
    let [d0, d1] = o.domain();
    let cluster_gap = (d1 - d0).mul_pow2(CLUSTER_GAP_LOG2);
    // First contact only: the leading breaks that are gaps proven separate
    // (no stop), and the end of the last of them when it was checked.
    let (mut passed, mut passed_to) = (0usize, None::<Rat>);
    for found in roots {
        if !matches!(found, Found::GaveUp | Found::Failed(_)) {
            stats.candidates += 1;
        }
        let mut pending = vec![(found, true)];
        while let Some((found, may_split)) = pending.pop() {
            match found {
                Found::Root(mut r) => {
                    let mut p = touch_at(o, &mut r, zeros);
                    if !p.touch {
                        continue;
                    }
                    let mut instant = o.refine(&mut r, q);
                    if p.single().is_none() {
                        p = touch_at(o, &mut r, zeros);
                        if !p.touch {
                            continue;
                        }
                    }
                    instant.certified &= p.single() == Some(Configuration::ExternalTouch);
                    out.push(Break::Contact(instant, Some(r)), d0, d1);
                }
                Found::Cluster(mut r) => {
                    if !touch_at(o, &mut r, zeros).touch {
                        // No touch is possible anywhere in it.
                        continue;
                    }
                    let split = if may_split { o.split(&r, q) } else { None };
                    match split {
                        Some(parts) => {
                            pending.extend(parts.into_iter().rev().map(|f| (f, false)));
                        }
                        None => {
                            let (lo, hi) = o.ends(&r);
                            if &hi - &lo > cluster_gap {
                                out.push(
                                    Break::Gap(lo, hi, "roots not separated (cluster)"),
                                    d0,
                                    d1,
                                );
                            } else {
                                let c = Instant {
                                    lo,
                                    hi,
                                    certified: false,
                                };
                                out.push(Break::Contact(c, None), d0, d1);
                            }
                        }
                    }
                }
                Found::Gap { lo, hi, reason } => out.push(Break::Gap(lo, hi, reason), d0, d1),
                Found::GaveUp => return Ok(None),
                Found::Failed(e) => return Err(e),
            }
        }
        if opts.first_contact_only {
            // A gap that the oracle's other certificates prove separate
            // throughout is no stop: the first contact lies past it. It is
            // kept, for the timeline to settle it as the full query's does
            // (the pieces around it are read at samples, which a gap's
            // undecided roots would not allow across it). One that a later
            // gap joined is checked again.
            if passed > 0
                && !matches!(&out.breaks[passed - 1], Break::Gap(_, hi, _) if Some(hi) == passed_to.as_ref())
            {
                passed -= 1;
            }
            while let Some(Break::Gap(lo, hi, _)) = out.breaks.get(passed) {
                if !separate_on(o, lo, hi) {
                    break;
                }
                passed_to = Some(hi.clone());
                passed += 1;
            }
            if passed < out.breaks.len() {
                out.breaks.truncate(passed + 1);
                out.stopped = true;
                break;
            }
        }
    }
    Ok(Some(out))
}

/// Whether the oracle's certificates for gaps ([`Oracle::settle`]) prove
/// the state separate on the whole of `[lo, hi]`.
fn separate_on<O: Oracle>(o: &O, lo: &Rat, hi: &Rat) -> bool {
    let gap = Item::Gap(Gap {
        lo: lo.clone(),
        hi: hi.clone(),
        reason: String::new(),
        witness: None,
    });
    o.settle(vec![gap])
        .iter()
        .all(|item| matches!(item, Item::Segment(s) if s.state == State::Separate && s.certified))
}

/// Runs Algorithm 1 of the paper on the arithmetic `o`.
///
/// 1. The state at `t0`; a first-contact query that is not separate there
///    stops (before any set-up, [`Oracle::prepare`]).
/// 2. The branch: `sr0 ≢ 0` — the candidates are the roots of `sr0`
///    (Theorem 5.2); `sr0 ≡ 0`, `sr11 ≢ 0` — touching at a non-root `δ` of
///    `sr11` means touching throughout (Theorem 5.5), otherwise the
///    candidates are the roots of `sr11` (Theorem 5.4); `sr0 ≡ sr11 ≡ 0` —
///    the state at `t0` throughout (Theorem 5.6).
/// 3. Each candidate in increasing order is a contact when Theorem 3.10(2)
///    says "external touch" there (up to the first with
///    `first_contact_only`); an attempt that gives up is replaced by the
///    oracle's next one.
/// 4. The timeline: the span cut at the contacts and gaps, each piece's
///    state read at a rational sample inside (Theorem 5.1).
///
/// # Errors
///
/// What the oracle's set-up or candidate streams return: a documented
/// effort bound reached ([`CcdError::Effort`]) or a broken invariant.
pub fn run<O: Oracle>(mut o: O, opts: &Options) -> Result<Outcome, CcdError> {
    let mut stats = Stats {
        path: O::PATH,
        ..Stats::default()
    };
    // A first-contact query reads the state at t0 before any set-up, to
    // stop there when the bodies are proven not separate (a guessed state
    // goes on as a full query does, which may leave the span a gap); a full
    // query sets up first (the exact arithmetic then reads t0 off f(λ; t)).
    let t0 = o.domain()[0].clone();
    if !opts.first_contact_only {
        o.prepare()?;
    }
    let state0 = state_at(&o, &t0);
    let stop_early = opts.first_contact_only && state0.certified && state0.state != State::Separate;
    let mut walk = Walk::default();
    let mut throughout = None;
    if !stop_early {
        if opts.first_contact_only {
            o.prepare()?;
        }
        match plan(&mut o, state0, &mut stats) {
            Plan::Throughout(d, zeros) => throughout = Some((d, zeros)),
            Plan::Undecided(why) => {
                let [d0, d1] = o.domain().clone();
                walk.push(Break::Gap(d0.clone(), d1.clone(), why), &d0, &d1);
            }
            Plan::Roots(q, zeros) => {
                for attempt in 0.. {
                    let Some(c) = o.candidates(q, attempt) else {
                        return Err(CcdError::Internal(format!(
                            "no attempt decided the roots of {q:?}"
                        )));
                    };
                    let mut tried = Stats {
                        deg_candidates: c.degree,
                        ..stats.clone()
                    };
                    if let Some(w) = walk_candidates(&o, q, zeros, c.roots, opts, &mut tried)? {
                        walk = w;
                        walk.zeros = zeros;
                        stats = tried;
                        break;
                    }
                }
            }
        }
    }
    let mut outcome = assemble(&o, opts, state0, throughout, stop_early, walk)?;
    o.stats(&mut stats);
    outcome.stats = stats;
    Ok(outcome)
}
