//! Algorithm 1 (Section 5): the branches of Theorems 5.2 and 5.4–5.6, the
//! touch test of Theorem 3.10(2) at each candidate, and the walk over the
//! candidates.

use crate::assemble::{assemble, Break, Walk};
use crate::decide::{possible_with, Possible};
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
/// a touch is ruled out or decided. At an `isolated` root, before level
/// [`Oracle::CERTIFICATES_BEFORE_LEVEL`], the certificates of
/// [`other_certificates`] first.
fn touch_at<O: Oracle>(o: &O, r: &mut O::Root, zeros: &[Quantity], isolated: bool) -> Possible {
    let mut p = Possible::default();
    for level in 0..O::LEVELS {
        if isolated && O::CERTIFICATES_BEFORE_LEVEL == Some(level) {
            if let Some(c) = other_certificates(o, r) {
                return Possible::only(c);
            }
        }
        p = possible_with(&mut *o.signs(At::Root(r), level), zeros, true);
        if !p.touch || p.single().is_some() {
            break;
        }
    }
    p
}

/// The configuration at an isolated root `α` of the candidates without
/// its signs, when one of two certificates proves it:
/// * the states at the ends `lo < α < hi` of its enclosure, read at those
///   samples: the state is constant between consecutive candidates
///   (Theorem 5.1), and separate (disjoint closed bodies) and overlapping
///   (interiors meeting) are both open conditions in time, so separate on
///   one side and overlapping on the other make `α` neither: an external
///   touch;
/// * overlapping on both sides, and a point of both interiors throughout
///   the enclosure ([`Oracle::interiors_meet`]): overlapping at `α`.
///
/// `None` otherwise (separate on both sides: a grazing touch is possible,
/// which only the signs decide).
fn other_certificates<O: Oracle>(o: &O, r: &O::Root) -> Option<Configuration> {
    let (lo, hi) = o.ends(r);
    if lo >= hi {
        return None;
    }
    let (before, after) = (state_at(o, &lo), state_at(o, &hi));
    if !(before.certified && after.certified) {
        return None;
    }
    match (before.state, after.state) {
        (State::Separate, State::Overlap) | (State::Overlap, State::Separate) => {
            Some(Configuration::ExternalTouch)
        }
        (State::Overlap, State::Overlap) if o.interiors_meet(r) => Some(Configuration::Overlap),
        _ => None,
    }
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
                    let mut p = touch_at(o, &mut r, zeros, true);
                    if !p.touch {
                        continue;
                    }
                    let mut instant = o.refine(&mut r, q);
                    if p.single().is_none() {
                        p = touch_at(o, &mut r, zeros, true);
                        if !p.touch {
                            continue;
                        }
                    }
                    instant.certified &= p.single() == Some(Configuration::ExternalTouch);
                    out.push(Break::Contact(instant, Some(r)), d0, d1);
                }
                Found::Cluster(mut r) => {
                    if !touch_at(o, &mut r, zeros, false).touch {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::decide::{SignSet, Signs, VarSet};
    use crate::oracle::Candidates;
    use ccd_classify::{classify, SignData};
    use ccd_timeline::{Geometry, Path};
    use std::cell::Cell;

    /// Signs of a state off every root: a combination Theorem 3.10
    /// classifies as `c`, with `sr0 ≠ 0`.
    struct Off(SignData);
    impl Signs for Off {
        fn sign(&mut self, q: Quantity) -> SignSet {
            let s = &self.0;
            SignSet::exactly(match q {
                Quantity::Sr22 => s.sr22,
                Quantity::Sr20 => s.sr20,
                Quantity::Sr11 => s.sr11,
                Quantity::Sr10 => s.sr10,
                Quantity::Sr0 => s.sr0,
                Quantity::Var => unreachable!("read through variations"),
            })
        }
        fn variations(&mut self) -> VarSet {
            VarSet::exactly(self.0.var)
        }
    }

    /// Signs at the root that no level decides.
    struct Unknown;
    impl Signs for Unknown {
        fn sign(&mut self, _q: Quantity) -> SignSet {
            SignSet::ANY
        }
        fn variations(&mut self) -> VarSet {
            VarSet::exactly(0)
        }
    }

    fn signs_of(c: Configuration) -> SignData {
        let s = [-1, 0, 1];
        for (a, b, d, e, v) in
            (0..3 * 3 * 3 * 3 * 5).map(|i| (i % 3, i / 3 % 3, i / 9 % 3, i / 27 % 3, i / 81))
        {
            for sr0 in [-1, 1] {
                let data = SignData {
                    sr22: s[a],
                    sr20: s[b],
                    sr11: s[d],
                    sr10: s[e],
                    sr0,
                    var: v,
                };
                if classify(&data) == c {
                    return data;
                }
            }
        }
        unreachable!("every configuration off a root has its signs")
    }

    /// One isolated root in `[1/4, 3/4]`: `before` left of it, `after`
    /// right of it, the root's own signs never decided.
    struct Staged {
        domain: [Rat; 2],
        before: Configuration,
        after: Configuration,
        meet: bool,
        witness_asked: Cell<bool>,
    }

    impl Oracle for Staged {
        type Root = ();
        const PATH: Path = Path::Exact;
        const LEVELS: usize = 2;
        const CERTIFICATES_BEFORE_LEVEL: Option<usize> = Some(1);
        fn domain(&self) -> &[Rat; 2] {
            &self.domain
        }
        fn time(&self, x: &Rat) -> Rat {
            x.clone()
        }
        fn signs<'s>(&'s self, at: At<'s, ()>, _level: usize) -> Box<dyn Signs + 's> {
            match at {
                At::Sample(x) if *x < Rat::from_frac(1, 2) => Box::new(Off(signs_of(self.before))),
                At::Sample(_) => Box::new(Off(signs_of(self.after))),
                At::Root(()) => Box::new(Unknown),
            }
        }
        fn guess(&self, _x: &Rat) -> State {
            unreachable!("samples are decided")
        }
        fn vanishes(&mut self, _q: Quantity) -> Vanishing {
            Vanishing::Not(None)
        }
        fn candidates(&self, _q: Quantity, _attempt: usize) -> Option<Candidates<'_, ()>> {
            None
        }
        fn ends(&self, _r: &()) -> (Rat, Rat) {
            (Rat::from_frac(1, 4), Rat::from_frac(3, 4))
        }
        fn interiors_meet(&self, _r: &()) -> bool {
            self.witness_asked.set(true);
            self.meet
        }
        fn refine(&self, _r: &mut (), _q: Quantity) -> Instant {
            unreachable!("not refined here")
        }
        fn geometry(&self, _r: &mut (), _zeros: &[Quantity], _instant: &Instant) -> Geometry {
            unreachable!("no geometry here")
        }
        fn geometry_at(&self, _x: &Rat, _zeros: &[Quantity]) -> Geometry {
            unreachable!("no geometry here")
        }
        fn touch_between_contacts(&self, _x: &Rat, d: Decided) -> Result<Decided, CcdError> {
            Ok(d)
        }
        fn stats(&self, _stats: &mut Stats) {}
    }

    /// The states on both sides decide a touch only where they differ;
    /// overlapping on both sides needs the interior witness; separate on
    /// both sides (a possible graze) and a cluster are left to the signs.
    #[test]
    fn other_certificates_decide_only_what_they_prove() {
        use Configuration::{ExternalTouch, Overlap, Separate};
        let at = |before, after, meet, isolated| {
            let o = Staged {
                domain: [Rat::zero(), Rat::one()],
                before,
                after,
                meet,
                witness_asked: Cell::new(false),
            };
            (
                touch_at(&o, &mut (), &[Quantity::Sr0], isolated).single(),
                o.witness_asked.get(),
            )
        };
        assert_eq!(
            at(Separate, Overlap, false, true),
            (Some(ExternalTouch), false)
        );
        assert_eq!(
            at(Overlap, Separate, false, true),
            (Some(ExternalTouch), false)
        );
        assert_eq!(at(Overlap, Overlap, true, true), (Some(Overlap), true));
        assert_eq!(at(Overlap, Overlap, false, true), (None, true));
        assert_eq!(at(Separate, Separate, true, true), (None, false));
        assert_eq!(at(Separate, Overlap, true, false), (None, false));
    }
}
