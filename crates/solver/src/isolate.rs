//! Real root isolation by Bernstein subdivision and Descartes' rule of signs.
//!
//! For a squarefree polynomial `p` of degree `n` with Bernstein coefficients
//! `b_0..b_n` over `[lo, hi]`, the number of roots in the open interval is
//! `Var(b) − 2k` for some `k >= 0` (Descartes' rule in Bernstein form), so
//! `Var(b) = 0` proves there is none and `Var(b) = 1` proves there is exactly
//! one. Otherwise the interval is halved by de Casteljau's algorithm. For a
//! squarefree `p` this terminates (the "two-circle" theorem).
//!
//! Roots come out lazily and in increasing order (depth-first, left half
//! first), so a caller that wants only the earliest root isolates no other.
//!
//! Every node first tries the `f64`-interval filter; a node with a
//! coefficient whose sign the filter cannot prove is recomputed in exact
//! integers, and stays exact while its signs need it.
//!
//! [`RootIter::filtered`] starts instead from enclosures of the Bernstein
//! coefficients that the caller computed without forming the polynomial
//! (the closed form of `sr0` in `f64` Bernstein arithmetic with a proven
//! error bound): it never goes exact, and stops as undecided where the
//! filter cannot sign a coefficient, so the caller can fall back to the
//! exact polynomial.

use crate::filter_bernstein::FilterBernstein;
use crate::model::{SignModel, SignProbe};
use crate::root::RealRoot;
use ccd_arith::{Dyadic, Int, Interval, Rat};
use ccd_poly::{Bernstein, Substitution};
use std::sync::Arc;

/// Subdivision depth at which a filter-only isolation gives up: the
/// filter cannot separate roots closer than this (or a multiple root).
const FILTER_DEPTH: u32 = 64;

/// The root of `slope` between `u` and `v`, where its values `su`, `sv`
/// have opposite signs, by regula falsi (Illinois: the end kept twice in a
/// row has its value halved), at most [`PROSPECT_STEPS`] steps or until the
/// bracket is `width` wide: its midpoint then.
fn slope_root(
    slope: impl Fn(f64) -> f64,
    (mut u, mut su): (f64, f64),
    (mut v, mut sv): (f64, f64),
    width: f64,
) -> f64 {
    let mut side = 0;
    for _ in 0..PROSPECT_STEPS {
        if v - u <= width {
            break;
        }
        let m = (u * sv - v * su) / (sv - su);
        let m = if u < m && m < v { m } else { 0.5 * (u + v) };
        let sm = slope(m);
        if sm == 0.0 {
            return m;
        }
        if (sm < 0.0) == (su < 0.0) {
            (u, su) = (m, sm);
            if side == -1 {
                sv *= 0.5;
            }
            side = -1;
        } else {
            (v, sv) = (m, sm);
            if side == 1 {
                su *= 0.5;
            }
            side = 1;
        }
    }
    0.5 * (u + v)
}

/// Samples of the slope in [`RootIter::filter_may_decide`].
const PROSPECT_SAMPLES: usize = 16;

/// A value below this fraction of the largest sampled one needs its
/// enclosure in [`RootIter::filter_may_decide`] (any other is far from 0).
const PROSPECT_NEAR: f64 = 1.0 / (1u64 << 20) as f64;

/// Steps (regula falsi) that close in on a critical point's bracket in
/// [`RootIter::filter_may_decide`], at most.
const PROSPECT_STEPS: usize = 24;

/// The bracket width (a fraction of the span) at which
/// [`RootIter::filter_may_decide`] stops: `2^(−28)`, where a double
/// root's value is far below any `f64` enclosure's width.
const PROSPECT_WIDTH: f64 = 1.0 / (1u64 << 28) as f64;

enum Coeffs {
    Filter(FilterBernstein),
    Exact(Bernstein),
}

struct Node {
    lo: Rat,
    hi: Rat,
    depth: u32,
    coeffs: Coeffs,
    cluster: Cluster,
}

/// What a node's ancestry says about a root cluster (see
/// [`RootIter::zoom`]): the sign variations of its parent, for how many
/// generations they have not dropped, the zoom factor `2^speed` for the
/// next Newton step, and `open_at`, the width `2^(−open_at)` of the last
/// node where [`RootIter::convex_exclusion`] stayed open in an exact
/// isolation (its descendants retry only once they are
/// `2^(EXCLUSION_BITS/4)` narrower, where a miss it could not reach may
/// come within reach; a filter-only isolation, bounded by
/// [`FILTER_DEPTH`], retries every streak).
#[derive(Clone, Copy, Debug)]
struct Cluster {
    var: usize,
    streak: u32,
    speed: u32,
    open_at: Option<i64>,
}

impl Default for Cluster {
    fn default() -> Cluster {
        Cluster {
            var: 0,
            streak: 0,
            speed: MIN_SPEED,
            open_at: None,
        }
    }
}

/// Generations with unchanged sign variations (≥ 2) before a Newton zoom
/// is tried: the roots then sit in a cluster 2⁻⁸ of the node's width or
/// smaller, where bisection would spend one level per bit.
const ZOOM_STREAK: u32 = 8;
/// The smallest zoom, `2^2`; a zoom that holds squares the factor
/// (`speed` doubles) up to `2^MAX_SPEED`, one that fails halves it.
const MIN_SPEED: u32 = 2;
const MAX_SPEED: u32 = 1 << 15;

// A node holds its coefficient vectors behind pointers already; the stack
// is short (one path of the subdivision tree), so its size does not matter.
#[allow(clippy::large_enum_variant)]
enum Item<M: SignModel + Clone> {
    Root(RealRoot<M>),
    Node(Node),
}

/// What [`RootIter`] reads off a node's coefficient signs: the sign
/// variations (zeros skipped) and the signs of the first and last
/// coefficient (the signs of `p` at the node's ends).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct SignSummary {
    var: usize,
    first: i32,
    last: i32,
}

impl SignSummary {
    /// One pass over the coefficients' signs; `None` if one of them is
    /// undecided (`None`) or there is none.
    fn of(signs: impl IntoIterator<Item = Option<i32>>) -> Option<SignSummary> {
        let mut signs = signs.into_iter();
        let first = signs.next()??;
        let (mut var, mut last, mut nonzero) = (0, first, first);
        for s in signs {
            let s = s?;
            if s != 0 {
                if nonzero != 0 && s != nonzero {
                    var += 1;
                }
                nonzero = s;
            }
            last = s;
        }
        Some(SignSummary { var, first, last })
    }
}

/// The stack an isolation starts from: `root`, between the exact roots at
/// its ends where `(at_lo, at_hi)` says there are (popped in order).
fn first_stack<M: SignModel + Clone>(
    base: &M,
    root: Node,
    (at_lo, at_hi): (bool, bool),
) -> Vec<Item<M>> {
    let end = |x: &Rat| Item::Root(RealRoot::exact(base.clone(), x.clone()));
    let mut stack = Vec::with_capacity(3);
    if at_hi {
        stack.push(end(&root.hi));
    }
    let lo_root = at_lo.then(|| end(&root.lo));
    stack.push(Item::Node(root));
    stack.extend(lo_root);
    stack
}

impl Node {
    /// The root node `[lo, hi]` from the filter's coefficients.
    fn filter(lo: &Rat, hi: &Rat, f: FilterBernstein) -> Node {
        Node {
            lo: lo.clone(),
            hi: hi.clone(),
            depth: 0,
            coeffs: Coeffs::Filter(f),
            cluster: Cluster::default(),
        }
    }

    /// `⌊−log₂(hi − lo)⌋`, within one.
    fn log_width(&self) -> i64 {
        let w = &self.hi - &self.lo;
        w.denom().bits() as i64 - w.numer().bits() as i64
    }

    #[cfg(test)]
    fn exact(p: &ccd_poly::ZPoly, lo: Rat, hi: Rat, depth: u32) -> Node {
        Node::with_exact(Bernstein::from_power(p, &lo, &hi), depth)
    }

    /// The node of exact coefficients `b`, on `b`'s interval.
    fn with_exact(b: Bernstein, depth: u32) -> Node {
        Node {
            lo: b.lo().clone(),
            hi: b.hi().clone(),
            depth,
            coeffs: Coeffs::Exact(b),
            cluster: Cluster::default(),
        }
    }

    /// Prefers the float form of exact coefficients whenever the filter can
    /// sign every coefficient (and `float` allows it).
    fn from_exact_bernstein(b: Bernstein, depth: u32, float: bool, cluster: Cluster) -> Node {
        let (lo, hi) = (b.lo().clone(), b.hi().clone());
        let f = float
            .then(|| FilterBernstein::from_exact(b.coeffs(), b.scale().signum()))
            .filter(FilterBernstein::decided);
        let coeffs = match f {
            Some(f) => Coeffs::Filter(f),
            None => Coeffs::Exact(b),
        };
        Node {
            lo,
            hi,
            depth,
            coeffs,
            cluster,
        }
    }

    /// The summary of the coefficients' signs (`None` if the filter
    /// leaves one open).
    fn signs(&self) -> Option<SignSummary> {
        match &self.coeffs {
            Coeffs::Filter(f) => match f.nonzero_variations() {
                Some((var, first, last)) => Some(SignSummary { var, first, last }),
                None => SignSummary::of(f.signs()),
            },
            Coeffs::Exact(b) => {
                let s = b.scale().signum();
                SignSummary::of(b.coeffs().iter().map(|c| Some(c.signum() * s)))
            }
        }
    }

    /// The sign `s` shared by every second difference of the coefficients,
    /// when each is proven nonzero: then `s·p″ > 0` on the whole node (the
    /// Bernstein coefficients of `p″` are `n(n − 1)/w²` times them, and a
    /// Bernstein polynomial lies in the hull of its coefficients).
    fn convexity(&self) -> Option<i32> {
        let mut all = None;
        let mut agree = |d: Option<i32>| match (d, all) {
            (Some(d), None) if d != 0 => {
                all = Some(d);
                true
            }
            (Some(d), Some(s)) => d == s,
            _ => false,
        };
        let alike = match &self.coeffs {
            Coeffs::Filter(f) => f.second_difference_signs().all(&mut agree),
            Coeffs::Exact(b) => {
                let c = b.coeffs();
                (0..c.len().saturating_sub(2)).all(|i| {
                    agree(Some(
                        (&(&c[i + 2] - &c[i + 1]) - &(&c[i + 1] - &c[i])).signum(),
                    ))
                })
            }
        };
        all.filter(|_| alike)
    }

    /// Halves the node; returns the children and the sign of `p` at the
    /// split point when the coefficients prove it. The children of an exact
    /// node go back to the float form only if `float`.
    fn split(self, float: bool) -> (Node, Node, Option<i32>) {
        let mid = Rat::midpoint(&self.lo, &self.hi);
        let depth = self.depth + 1;
        match self.coeffs {
            Coeffs::Filter(f) => {
                let (l, r) = f.split_half();
                let s = l.sign_at_hi();
                let left = Node {
                    lo: self.lo,
                    hi: mid.clone(),
                    depth,
                    coeffs: Coeffs::Filter(l),
                    cluster: self.cluster,
                };
                let right = Node {
                    lo: mid,
                    hi: self.hi,
                    depth,
                    coeffs: Coeffs::Filter(r),
                    cluster: self.cluster,
                };
                (left, right, s)
            }
            Coeffs::Exact(b) => {
                let (l, r) = b.split_half();
                let s = l.sign_at_hi();
                (
                    Node::from_exact_bernstein(l, depth, float, self.cluster),
                    Node::from_exact_bernstein(r, depth, float, self.cluster),
                    Some(s),
                )
            }
        }
    }

    /// Marks the shared endpoint as an exact root in the float form.
    fn set_endpoint_zero(&mut self, at_hi: bool) {
        if let Coeffs::Filter(f) = &mut self.coeffs {
            f.set_end_zero(at_hi);
        }
    }
}

/// The real roots of a squarefree function (an integer polynomial, or a
/// [`SignModel`] of one) in a closed interval, isolated lazily in
/// increasing order. Built by [`crate::isolate`] or [`RootIter::filtered`].
pub struct RootIter<M: SignModel + Clone = Arc<SignProbe>> {
    base: M,
    stack: Vec<Item<M>>,
    /// Filter-only mode ([`RootIter::filtered`]): never go exact.
    filter_only: bool,
    /// A filter-only isolation met a sign it could not prove.
    undecided: bool,
    /// Splits of nodes with unsigned coefficients left (filter only).
    budget: usize,
    /// Filter nodes that had to be redone exactly, each by a conversion from
    /// the power basis; past [`FLOAT_FAILURES`] the filter does not pay on
    /// this polynomial (coefficients beyond `f64`'s range, say) and the
    /// children of exact nodes stay exact.
    float_failures: u32,
    /// Points where [`RootIter::convex_exclusion`] or
    /// [`RootIter::float_witness`] found `p` of the sign opposite to the
    /// ends of a node, with the sign there: a
    /// node around one with ends of another sign holds roots, and is not
    /// tested again.
    witnesses: Vec<(Rat, i32)>,
    /// Whether the function is proven squarefree (so that
    /// [`RootIter::convex_exclusion`] settles every near miss it can
    /// reach): by construction in an exact isolation, by one modular
    /// image ([`Residues::proves_squarefree`](ccd_poly::Residues::proves_squarefree))
    /// in a filter-only one, on first need.
    squarefree: Option<bool>,
    /// Nodes split so far.
    splits: usize,
    /// Exact work done so far, in word operations ([`exact_work`]); the
    /// isolation stops once it passes `max_work` ([`RootIter::exhausted`]).
    work: u64,
    max_work: u64,
    /// The last exact conversion's substitution into `p`, from which a
    /// conversion on an interval inside it starts
    /// ([`Bernstein::from_power_nested`]): a Newton zoom's interval lies
    /// in the node it zooms from, itself the previous zoom's.
    substitution: Option<Substitution>,
}

/// The default bound on an isolation's exact work (`exact_work`), about
/// a second of this machine's time with num-bigint (docs/termination.md).
pub const MAX_EXACT_WORK: u64 = 4_000_000_000;

/// The word operations of one exact Bernstein operation producing `b`
/// (a de Casteljau split or a change of basis: `(n + 1)²` products of
/// numbers as long as `b`'s longest coefficient by a factor of `factor`
/// bits — 1 for a halving, the cut's numerator for another split, the
/// new end's for a change of basis).
fn exact_work(b: &Bernstein, factor: u64) -> u64 {
    let n = b.degree() as u64 + 1;
    let bits = b.coeffs().iter().map(Int::bits).max().unwrap_or(0);
    n * n * (bits / 64 + 1) * (factor / 64 + 1)
}

/// The bits of the longer end of `b`'s interval (the factor of a change
/// of basis to it, [`exact_work`]).
fn end_bits(b: &Bernstein) -> u64 {
    [b.lo(), b.hi()]
        .iter()
        .map(|r| r.numer().bits().max(r.denom().bits()))
        .max()
        .unwrap_or(0)
}

/// The finest grid (in bits past the node's ends) on which
/// [`RootIter::convex_exclusion`] evaluates before it gives up: for a
/// node whose ends have about as many bits as its width, a near miss by
/// about `2^(−500)` of the node is the closest it settles (more when the
/// ends are longer).
const EXCLUSION_BITS: u64 = 1024;
/// The rounds of [`RootIter::convex_exclusion`] (two exact jets each)
/// before it gives up.
const EXCLUSION_ROUNDS: usize = 16;

/// What [`RootIter::convex_exclusion`] found.
enum Exclusion {
    /// The node holds no root.
    RootFree,
    /// A point of the node where `p` is zero or has the sign opposite to
    /// its ends', and the sign of `p` there: the node holds roots.
    Witness(Rat, i32),
    /// Neither within the test's budget.
    Open,
}

/// See [`RootIter::float_failures`].
const FLOAT_FAILURES: u32 = 8;

impl RootIter<Arc<SignProbe>> {
    /// `p` must be squarefree, nonzero and of degree >= 1; `lo < hi`.
    pub(crate) fn new(base: Arc<SignProbe>, lo: &Rat, hi: &Rat) -> RootIter {
        let poly = base.exact();
        let (first, last) = (poly.sign_at(lo), poly.sign_at(hi));
        // The filter straight from the power basis when the ends are not
        // roots; the exact conversion otherwise (or if it cannot sign).
        let float = (first != 0 && last != 0)
            .then(|| FilterBernstein::from_power(poly, lo, hi))
            .flatten();
        let root = match float {
            Some(f) => Node::filter(lo, hi, f),
            None => Node::from_exact_bernstein(
                Bernstein::from_power(poly, lo, hi),
                0,
                true,
                Cluster::default(),
            ),
        };
        let stack = first_stack(&base, root, (first == 0, last == 0));
        RootIter {
            base,
            stack,
            filter_only: false,
            undecided: false,
            budget: 0,
            float_failures: 0,
            witnesses: Vec::new(),
            squarefree: Some(true),
            splits: 0,
            work: 0,
            max_work: MAX_EXACT_WORK,
            substitution: None,
        }
    }
}

impl<M: SignModel + Clone> RootIter<M> {
    /// The roots in `[lo, hi]` of the squarefree function of `model`, from
    /// `coeffs`: enclosures of its Bernstein coefficients over `[lo, hi]`
    /// times one positive constant. Only the filter is used: a node with a
    /// coefficient it cannot sign (an enclosure holding 0, as for an exact
    /// zero) is split, within a budget of `2n + 16` such splits; past that,
    /// at a root at `lo` or `hi` whose coefficient's enclosure is not the
    /// point 0, at a multiple root, or at roots closer than `2^(−64)` of
    /// the interval, the iteration ends early and [`RootIter::undecided`]
    /// is `true`. An end coefficient enclosed by the point 0 proves a root
    /// at that end (the end coefficients are the end values), which is
    /// yielded. Every root it yields is proven.
    pub fn filtered(model: M, lo: &Rat, hi: &Rat, coeffs: &[Interval]) -> RootIter<M> {
        let f = FilterBernstein::from_intervals(coeffs);
        let signs: Vec<Option<i32>> = f.signs().collect();
        let zero = |s: &Option<i32>| *s == Some(0);
        // An identically zero function (every coefficient the point 0)
        // has no isolated roots to yield.
        let undecided =
            coeffs.is_empty() || lo >= hi || signs.contains(&None) || signs.iter().all(zero);
        let stack = if undecided {
            Vec::new()
        } else {
            let ends = (zero(&signs[0]), zero(&signs[signs.len() - 1]));
            first_stack(&model, Node::filter(lo, hi, f), ends)
        };
        RootIter {
            base: model,
            stack,
            filter_only: true,
            undecided,
            budget: 2 * coeffs.len() + 16,
            float_failures: 0,
            witnesses: Vec::new(),
            squarefree: None,
            splits: 0,
            work: 0,
            max_work: MAX_EXACT_WORK,
            substitution: None,
        }
    }

    /// Whether a filter-only isolation ([`RootIter::filtered`]) of `model`
    /// on `[lo, hi]` can be expected to decide: a guess that only picks a
    /// path (every answer is proven either way). `false` when the
    /// certified enclosure ([`SignModel::float_sign_at`]) cannot sign `p`
    /// at an end, or at a critical point of `p` — located in `f64` by 16
    /// samples of the slope and regula falsi where it changes sign — where
    /// the filter's nodes could not separate a
    /// cluster either (a double root, a touch; roots or a complex pair
    /// closer than its precision, a near miss). Costs about 16 `f64`
    /// evaluations, a few more per critical point, and an enclosure only at
    /// values near 0.
    pub fn filter_may_decide(model: &M, lo: &Rat, hi: &Rat) -> bool {
        let (a, b) = (lo.to_f64(), hi.to_f64());
        let at = |i: usize| a + (b - a) * i as f64 / PROSPECT_SAMPLES as f64;
        let samples: Vec<(f64, f64)> = (0..=PROSPECT_SAMPLES)
            .map(|i| model.approx_value_and_slope(at(i)))
            .collect();
        // Only values near 0 next to the samples' largest need an
        // enclosure: any other is signed by it.
        let scale = samples.iter().fold(0.0f64, |m, (v, _)| m.max(v.abs()));
        let signed =
            |x: &Rat, v: f64| v.abs() > scale * PROSPECT_NEAR || model.float_sign_at(x).is_some();
        if !signed(lo, samples[0].0) || !signed(hi, samples[PROSPECT_SAMPLES].0) {
            return false;
        }
        let slope = |x: f64| model.approx_value_and_slope(x).1;
        let mut previous = samples[0].1;
        for (i, &(_, next)) in samples.iter().enumerate().skip(1) {
            if previous.is_nan() || next.is_nan() {
                return true;
            }
            if (previous < 0.0) != (next < 0.0) {
                // A critical point between.
                let m = slope_root(
                    slope,
                    (at(i - 1), previous),
                    (at(i), next),
                    (b - a) * PROSPECT_WIDTH,
                );
                let x = Rat::from_f64_exact(m);
                let value = model.approx_value_and_slope(m).0;
                if x.is_some_and(|x| lo < &x && &x < hi && !signed(&x, value)) {
                    return false;
                }
            }
            previous = next;
        }
        true
    }

    /// Whether a filter-only isolation stopped at a sign it could not
    /// prove: the roots it yielded are proven, but there may be more.
    pub fn undecided(&self) -> bool {
        self.undecided
    }

    /// Whether the isolation stopped because its exact work reached the
    /// bound ([`RootIter::with_max_work`]): the roots it yielded are proven,
    /// but there may be more. Never the case below the bound: every other
    /// isolation runs to the end.
    pub fn exhausted(&self) -> bool {
        self.work > self.max_work
    }

    /// The exact work done so far (word operations, [`MAX_EXACT_WORK`]).
    pub fn work(&self) -> u64 {
        self.work
    }

    /// The same isolation with another bound on its exact work (word
    /// operations; [`MAX_EXACT_WORK`] by default, `u64::MAX` for none).
    pub fn with_max_work(mut self, max_work: u64) -> Self {
        self.max_work = max_work;
        self
    }

    /// Counts the exact work that produced `b`.
    fn charge(&mut self, b: &Bernstein, factor: u64) {
        self.work = self.work.saturating_add(exact_work(b, factor));
    }

    /// Halves `node` and stacks the halves (left on top), with the split
    /// point itself when it is a root.
    fn split_and_push(&mut self, node: Node) {
        self.splits += 1;
        let (mut left, mut right, mid_sign) = node.split(self.float_failures < FLOAT_FAILURES);
        // The split point, as the halves have it (computed once).
        let mid = left.hi.clone();
        for child in [&left, &right] {
            if let Coeffs::Exact(b) = &child.coeffs {
                self.charge(b, 1);
            }
        }
        let mid_sign = mid_sign.unwrap_or_else(|| self.base.filtered_sign_at(&mid));
        if mid_sign == 0 {
            right.set_endpoint_zero(false);
        }
        self.stack.push(Item::Node(right));
        if mid_sign == 0 {
            left.set_endpoint_zero(true);
            self.stack
                .push(Item::Root(RealRoot::exact(self.base.clone(), mid)));
        }
        self.stack.push(Item::Node(left));
    }

    /// `p`'s exact Bernstein form on `[lo, hi]`, from the kept substitution
    /// where that is shorter (and kept in turn with `keep`:
    /// [`Bernstein::from_power_nested`]), its work charged.
    fn exact_on(&mut self, lo: &Rat, hi: &Rat, keep: bool) -> Bernstein {
        let b =
            Bernstein::from_power_nested(self.base.exact(), lo, hi, &mut self.substitution, keep);
        self.charge(&b, end_bits(&b));
        b
    }

    /// A Newton zoom into a root cluster (the Newton test of Sagraloff and
    /// Mehlhorn's ANewDsc): for a node `I` of width `w` whose `k ≥ 2` sign
    /// variations have not dropped for [`ZOOM_STREAK`] generations, the
    /// estimate `λ = m − k·p(m)/p′(m)` at the midpoint `m` (Newton's step
    /// for a `k`-fold root; exact values) picks the subinterval `I′` of
    /// width `w/N`, `N = 2^speed`, on the grid of `w/(4N)` around `λ`. If
    /// Descartes' rule proves the rest of `I` root-free (no sign variation
    /// in the Bernstein coefficients on either side, nonzero at the cuts:
    /// proven in intervals around `I`'s coefficients where they decide,
    /// else on the exact ones), `I′` replaces `I` and the next zoom is
    /// `N²`; otherwise `I` is
    /// returned for bisection and the next zoom is `√N`. A cluster of
    /// width `δ` then takes about `log log(w/δ)` zooms instead of
    /// `log(w/δ)` bisections. Every step is exact, so the roots kept are
    /// exactly those of `I`; and since a failed zoom falls back to a
    /// bisection and a successful one shrinks `I` at least fourfold, the
    /// isolation still terminates.
    fn zoom(&mut self, node: &mut Node, k: usize) -> Option<Node> {
        let speed = node.cluster.speed;
        // A failed zoom: slower next time, and not before another streak.
        node.cluster.speed = (speed / 2).max(MIN_SPEED);
        node.cluster.streak = 0;
        // Widths are powers of two here (halvings and zooms of [lo, hi] by
        // powers of two); anything else is left to bisection.
        let w = &node.hi - &node.lo;
        let e = w.dyadic_exponent().filter(|_| w.numer().is_one())?;
        let m = Rat::midpoint(&node.lo, &node.hi);
        let jet = self.base.exact_jet_at(&m);
        if jet.slope.is_zero() {
            return None;
        }
        // (λ − lo)/h = 2N − k·p(m)/p′(m)·4N/w with p(m) = V·2^(−v) and
        // p′(m) = S·2^(−s): one floor division of integers.
        let total = Int::one().shl(speed as u64 + 2);
        let shift = jet.slope_exp - jet.value_exp + e as i64 + speed as i64 + 2;
        let kv = &jet.value * &Int::from(k as i64);
        let (num, den) = if shift >= 0 {
            (kv.shl(shift as u64), jet.slope.clone())
        } else {
            (kv, jet.slope.shl(shift.unsigned_abs()))
        };
        let estimate = &total.shr_floor(1) - &num.div_floor(&den);
        let four = Int::from(4);
        let i = (estimate - Int::from(2)).clamp(Int::zero(), &total - &four);
        // Both cuts are dyadic splits of I's own coefficients; I′ itself
        // comes from the power basis (a split of a split would cut at a
        // non-dyadic ratio, with a rational scale to reduce), through the
        // previous zoom's substitution where that is shorter
        // ([`Bernstein::from_power_nested`]: `I′`'s offset in it has this
        // zoom's bits, not the whole descent's). Each side is
        // first tried in intervals around the coefficients
        // ([`FilterBernstein::side_root_free`]: the early zooms, up to
        // about 2⁻²⁴ of I, decide there), exactly only where they leave it
        // open.
        let cut = |j: &Int| Rat::new(j.clone(), total.clone()).expect("nonzero");
        let end = &i + &four;
        let filter = match &node.coeffs {
            Coeffs::Exact(b) => FilterBernstein::from_exact(b.coeffs(), b.scale().signum()),
            Coeffs::Filter(f) => f.clone(),
        };
        let mut converted = None;
        for (j, left, at_end) in [(&i, true, i.is_zero()), (&end, false, end == total)] {
            if at_end {
                continue;
            }
            match filter.side_root_free(&cut(j), left) {
                Some(true) => continue,
                Some(false) => return None,
                None => {}
            }
            let b = match &node.coeffs {
                Coeffs::Exact(b) => b,
                Coeffs::Filter(_) => {
                    converted.get_or_insert_with(|| self.exact_on(&node.lo, &node.hi, false))
                }
            };
            let (l, r) = b.split(&cut(j));
            let side = if left { l } else { r };
            let at_cut = if left {
                side.sign_at_hi()
            } else {
                side.sign_at_lo()
            };
            self.charge(&side, j.bits());
            if side.sign_variations() != 0 || at_cut == 0 {
                return None;
            }
        }
        let at = |j: &Int| &node.lo + &(&w * &cut(j));
        let middle = self.exact_on(&at(&i), &at(&end), true);
        let cluster = Cluster {
            var: k,
            streak: ZOOM_STREAK,
            speed: (speed * 2).min(MAX_SPEED),
            open_at: node.cluster.open_at,
        };
        Some(Node::from_exact_bernstein(
            middle,
            node.depth + 1,
            false,
            cluster,
        ))
    }

    /// A second-order exclusion test for a node whose coefficients are
    /// convex: with `g = s·σ·p`, `s` the sign of `p` at both ends and of
    /// every second difference ([`Node::convexity`]), `g″ > 0` on the node,
    /// so each tangent of `g` is a lower bound of `g` there. Between
    /// points `a < b` with `g(a), g(b) > 0` and `g′(a) < 0 < g′(b)`, the
    /// larger of the two tangents is at least its value `v` where they
    /// cross, and outside `[a, b]` `g` is monotone away from them; `v > 0`
    /// proves the node root-free. `a` and `b` close in on the minimum of
    /// `g` by secant steps on `g′` (exact jets at dyadic points, the
    /// precision doubling each round), one point on each side of it. A
    /// pair of complex roots at distance `ε` from the axis (a near miss)
    /// needs about `log₂(1/ε)` bits, and a handful of rounds instead of the
    /// bisections or Newton zooms that Descartes' rule needs to see them
    /// apart (those shrink the node to the width `ε`). A point with
    /// `g ≤ 0` is returned as a [`Exclusion::Witness`] of real roots; the
    /// node's ends not dyadic, or a round on the grid [`EXCLUSION_BITS`]
    /// past the bits of the node's ends spent without a decision (the
    /// grid otherwise twice as fine as the bracket, relative to the
    /// node), or [`EXCLUSION_ROUNDS`] spent, leave it [`Exclusion::Open`],
    /// and the node is subdivided as before. Every step is exact, so
    /// [`Exclusion::RootFree`] is a proof. The jets are not charged to the
    /// isolation's work budget: at most `2·EXCLUSION_ROUNDS + 2` of them
    /// per try, at points of at most `EXCLUSION_BITS + EXCLUSION_ROUNDS`
    /// bits past the node's ends, and in an exact isolation a cluster
    /// retries only after shrinking by `2^(EXCLUSION_BITS/4)`
    /// ([`Cluster::open_at`]).
    fn convex_exclusion(&self, node: &Node, s: i32) -> Exclusion {
        let (Some(lo), Some(hi)) = (
            Dyadic::from_rat_exact(&node.lo),
            Dyadic::from_rat_exact(&node.hi),
        ) else {
            return Exclusion::Open;
        };
        let base_bits = (-lo.e).max(-hi.e).max(0) as u64;
        let width = hi.sub(&lo);
        let log_node = -(width.m.bits() as i64 + width.e);
        // (x, g(x), g′(x)), exactly.
        let point = |x: Dyadic| {
            let j = self.base.exact_jet_at(&x.to_rat());
            let g = Dyadic {
                m: j.value,
                e: -j.value_exp,
            };
            let d = Dyadic {
                m: j.slope,
                e: -j.slope_exp,
            };
            if s < 0 {
                (x, g.neg(), d.neg())
            } else {
                (x, g, d)
            }
        };
        let (mut a, mut b) = (point(lo), point(hi));
        if a.1.signum() <= 0 || b.1.signum() <= 0 {
            return Exclusion::Open;
        }
        // g monotone on the node: its smaller end value is its minimum.
        if a.2.signum() >= 0 || b.2.signum() <= 0 {
            return Exclusion::RootFree;
        }
        // ⌊(num/den)·2^k⌋·2^(−k), for den > 0.
        let on_grid = |num: &Dyadic, den: &Dyadic, k: u64| Dyadic {
            m: Dyadic::quotient(&num.m, &den.m, num.e - den.e + k as i64, false).m,
            e: -(k as i64),
        };
        let inside =
            |x: &Dyadic, a: &Dyadic, b: &Dyadic| x.cmp_value(a).is_gt() && x.cmp_value(b).is_lt();
        let mut capped = false;
        for _ in 0..EXCLUSION_ROUNDS {
            // The value v where the tangents at a and b cross, times
            // g′(b) − g′(a) > 0: g(a)·rise + g′(a)·(g(a) − g(b) + g′(b)·w).
            let w = b.0.sub(&a.0);
            let rise = b.2.sub(&a.2);
            let v =
                a.1.mul(&rise)
                    .add(&a.2.mul(&a.1.sub(&b.1).add(&b.2.mul(&w))));
            if v.signum() > 0 {
                return Exclusion::RootFree;
            }
            // The grid: twice the bits of the bracket's width relative to
            // the node's (a secant step squares the error), past the
            // node's own.
            let log_w = -(w.m.bits() as i64 + w.e);
            let mut k = (2 * log_w - log_node + 8).max(base_bits as i64 + 8) as u64;
            // Past the cap, one last round on the cap's grid (the bracket's
            // bits roughly double each round, so without it the deepest
            // grid reached would jump with the depth of the miss).
            if k > base_bits + EXCLUSION_BITS {
                if capped {
                    return Exclusion::Open;
                }
                capped = true;
                k = base_bits + EXCLUSION_BITS;
            }
            // The secant root of g′ on [a, b], on the grid.
            let mut x = a.0.add(&on_grid(&a.2.neg().mul(&w), &rise, k));
            if !inside(&x, &a.0, &b.0) {
                let sum = a.0.add(&b.0);
                x = Dyadic {
                    m: sum.m,
                    e: sum.e - 1,
                };
            }
            let x = point(x);
            if x.1.signum() <= 0 {
                return Exclusion::Witness(x.0.to_rat(), s * x.1.signum());
            }
            let side = x.2.signum();
            if side == 0 {
                return Exclusion::RootFree;
            }
            // A point past the minimum: more than twice its distance from
            // x as the bracket's slope of g′ estimates it.
            let mut step = on_grid(
                &x.2.mul(&w)
                    .mul(&Dyadic::from_int(&Int::from(2 * side as i64))),
                &rise,
                k,
            );
            step.m += Int::one();
            let y = if side < 0 {
                x.0.add(&step)
            } else {
                x.0.sub(&step)
            };
            if side < 0 {
                a = x;
            } else {
                b = x;
            }
            if inside(&y, &a.0, &b.0) {
                let y = point(y);
                if y.1.signum() <= 0 {
                    return Exclusion::Witness(y.0.to_rat(), s * y.1.signum());
                }
                match y.2.signum() {
                    0 => return Exclusion::RootFree,
                    d if d < 0 => a = y,
                    _ => b = y,
                }
            }
        }
        Exclusion::Open
    }

    /// A cheap witness before [`RootIter::convex_exclusion`]'s exact
    /// jets: the minimum of `g = s·p` located to `2^(−24)` of the node by
    /// bisection on the sign of the model's `f64` guess of `g′` (no proof),
    /// then the sign of `p` there from the model's certified enclosure
    /// ([`SignModel::float_sign_at`]). A sign opposite to `s` proves real
    /// roots in the node (the ends have sign `s`), as the test's own
    /// witness would, without its jets; a near miss never yields one.
    fn float_witness(&self, node: &Node, s: i32) -> Option<(Rat, i32)> {
        let (x, sign) = self.float_minimum(node, s)?;
        let sign = sign?;
        (sign != s).then_some((x, sign))
    }

    /// The minimum of `g = s·p` on the node, located to `2^(−24)` of it by
    /// bisection on the sign of the model's `f64` guess of `g′` (no
    /// proof), and the sign of `p` there from the model's certified
    /// enclosure ([`SignModel::float_sign_at`]; `None` where it holds 0).
    /// `None` when the point falls outside the node.
    fn float_minimum(&self, node: &Node, s: i32) -> Option<(Rat, Option<i32>)> {
        let slope = |x: f64| f64::from(s) * self.base.approx_value_and_slope(x).1;
        let (mut u, mut v) = (node.lo.to_f64(), node.hi.to_f64());
        for _ in 0..24 {
            let m = 0.5 * (u + v);
            if slope(m) < 0.0 {
                u = m;
            } else {
                v = m;
            }
        }
        let x = Rat::from_f64_exact(0.5 * (u + v))?;
        if !(node.lo < x && x < node.hi) {
            return None;
        }
        let sign = self.base.float_sign_at(&x);
        Some((x, sign))
    }

    /// [`RootIter::squarefree`], decided on first need.
    fn proven_squarefree(&mut self) -> bool {
        *self.squarefree.get_or_insert_with(|| {
            let (image, kept) = self.base.residues();
            kept && image.proves_squarefree()
        })
    }

    /// Nodes split so far (bisections, of filter or exact nodes).
    pub fn splits(&self) -> usize {
        self.splits
    }

    /// Ends a filter-only isolation as undecided.
    fn give_up(&mut self) -> Option<RealRoot<M>> {
        self.undecided = true;
        self.stack.clear();
        None
    }
}

impl<M: SignModel + Clone> Iterator for RootIter<M> {
    type Item = RealRoot<M>;

    fn next(&mut self) -> Option<RealRoot<M>> {
        while let Some(item) = self.stack.pop() {
            if self.exhausted() {
                self.stack.clear();
                return None;
            }
            let node = match item {
                Item::Root(r) => return Some(r),
                Item::Node(n) => n,
            };
            let signs = match node.signs() {
                Some(signs) => signs,
                // Filter only: a coefficient it cannot sign (an exact zero,
                // say) may be signed in the halves; split, within budget.
                None if self.filter_only => {
                    // A cluster stalled for half a streak of generations
                    // whose halves the filter can no longer sign has
                    // reached the filter's precision: a multiple root or
                    // roots closer than it resolves (a touch, a near miss),
                    // which more halving does not separate.
                    let stalled = node.cluster.var >= 2 && node.cluster.streak >= ZOOM_STREAK / 2;
                    if node.depth >= FILTER_DEPTH || self.budget == 0 || stalled {
                        return self.give_up();
                    }
                    self.budget -= 1;
                    self.split_and_push(node);
                    continue;
                }
                None => {
                    // The filter cannot sign a coefficient: redo this node
                    // exactly.
                    self.float_failures += 1;
                    let b = self.exact_on(&node.lo, &node.hi, false);
                    self.stack.push(Item::Node(Node::with_exact(b, node.depth)));
                    continue;
                }
            };
            let SignSummary { var, first, last } = signs;
            if var == 0 {
                continue;
            }
            if var == 1 && first != 0 && last != 0 {
                return Some(RealRoot::isolated(
                    self.base.clone(),
                    node.lo,
                    node.hi,
                    first,
                ));
            }
            if self.filter_only && node.depth >= FILTER_DEPTH {
                return self.give_up();
            }
            let mut node = node;
            node.cluster.streak = if var == node.cluster.var {
                node.cluster.streak + 1
            } else {
                0
            };
            node.cluster.var = var;
            // A cluster that Descartes' rule has not resolved for a streak
            // of generations: first the convexity test, which settles a
            // near miss (no real root) at once, unless a witness (its own,
            // or a point where the filter proves the other sign) shows
            // roots; then, in an exact isolation, a Newton zoom. A
            // filter-only isolation, which does not zoom, tries the test
            // once every streak, and only on a function proven squarefree:
            // at a multiple root the test could never end (measured: +87 %
            // on a family whose `sr0` has a square factor).
            let streak = node.cluster.streak;
            // A filter-only isolation whose cluster first completes a
            // streak with ends of one sign: where the certified enclosure
            // cannot sign `p` at the cluster's minimum (a double root, or
            // roots or a complex pair closer than the filter resolves),
            // no filter node will separate the cluster either; give up
            // now rather than when its halves become unsignable. Not on a
            // function proven squarefree, whose near misses the convexity
            // test below settles exactly.
            if self.filter_only
                && var >= 2
                && streak == ZOOM_STREAK
                && first == last
                && first != 0
                && self
                    .float_minimum(&node, first)
                    .is_some_and(|(_, sign)| sign.is_none())
                && !self.proven_squarefree()
            {
                return self.give_up();
            }
            if var >= 2 && streak >= ZOOM_STREAK {
                let shown = |(x, sign): &(Rat, i32)| *sign != first && node.lo < *x && *x < node.hi;
                if first == last
                    && first != 0
                    && (!self.filter_only || streak % ZOOM_STREAK == 0)
                    && !self.witnesses.iter().any(shown)
                    && node.convexity() == Some(first)
                    && self.proven_squarefree()
                {
                    if let Some(witness) = self.float_witness(&node, first) {
                        self.witnesses.push(witness);
                    } else {
                        let log_width = node.log_width();
                        let due = node
                            .cluster
                            .open_at
                            .is_none_or(|at| log_width >= at + (EXCLUSION_BITS / 4) as i64);
                        match due.then(|| self.convex_exclusion(&node, first)) {
                            Some(Exclusion::RootFree) => continue,
                            Some(Exclusion::Witness(x, sign)) => self.witnesses.push((x, sign)),
                            Some(Exclusion::Open) if !self.filter_only => {
                                node.cluster.open_at = Some(log_width)
                            }
                            _ => {}
                        }
                    }
                }
            }
            if !self.filter_only && var >= 2 && node.cluster.streak >= ZOOM_STREAK {
                if let Some(zoomed) = self.zoom(&mut node, var) {
                    self.stack.push(Item::Node(zoomed));
                    continue;
                }
            }
            self.split_and_push(node);
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::{end_bits, exact_work, Coeffs, Exclusion, Node, RootIter, SignSummary};
    use crate::model::SignProbe;
    use crate::tests::{cluster, dyadic_node};
    use ccd_arith::{Int, Rat};
    use ccd_poly::ZPoly;
    use proptest::prelude::*;

    /// [`RootIter::convex_exclusion`] on the node `[lo, hi]` of `p`, when
    /// its preconditions hold (ends of one sign, convex coefficients).
    fn exclusion(p: &ZPoly, lo: &Rat, hi: &Rat) -> Option<(Exclusion, i32)> {
        let iter = RootIter::new(SignProbe::shared(p.clone()), lo, hi);
        let node = Node::exact(p, lo.clone(), hi.clone(), 0);
        let SignSummary { first, last, .. } = node.signs()?;
        (first == last && first != 0 && node.convexity() == Some(first))
            .then(|| (iter.convex_exclusion(&node, first), first))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(96))]
        /// A near miss (a complex pair `a ± 2^(−k)·i`) or a near hit (real
        /// roots `a ± 2^(−k)`) inside a dyadic node, times a linear factor
        /// with a root anywhere: "root-free" only when no root is in the
        /// node, a witness only inside it with the sign it claims (checked
        /// exactly), and within the test's reach (`k` up to 400 bits past
        /// the node) the near miss is settled and the near hit shown.
        #[test]
        fn convexity_test_is_sound_and_reaches_near_misses(
            (d, n) in (2i64..51).prop_flat_map(|d| (Just(d), 1..d)), k in 12u64..400, j in 4u64..9,
            hit in any::<bool>(), r in (-40i64..80, 1i64..40),
        ) {
            let a = Rat::from_frac(n, d);
            let cluster = cluster(&a, k, hit);
            let root = Rat::from_frac(r.0, r.1);
            let p = &cluster * &ZPoly::new(vec![-root.numer().clone(), root.denom().clone()]);
            // The dyadic node of width 2^(−j) around a, if the cluster fits.
            let (lo, hi) = dyadic_node(&a, j);
            let eps = Rat::dyadic(Int::one(), k);
            prop_assume!(lo < &a - &eps && &a + &eps < hi);
            let Some((found, s)) = exclusion(&p, &lo, &hi) else {
                return Ok(());
            };
            let inside = |x: &Rat| &lo <= x && x <= &hi;
            let real_in = (hit && inside(&a)) || inside(&root);
            match &found {
                Exclusion::RootFree => prop_assert!(!real_in, "root-free with a root inside"),
                &Exclusion::Witness(ref x, sign) => {
                    prop_assert!(&lo < x && x < &hi);
                    prop_assert_eq!(p.sign_at(x), sign);
                    prop_assert!(sign != s);
                }
                Exclusion::Open => {}
            }
            if k <= 400 && !inside(&root) {
                if hit {
                    prop_assert!(matches!(found, Exclusion::Witness(..)), "near hit not shown");
                } else {
                    prop_assert!(matches!(found, Exclusion::RootFree), "near miss not settled");
                }
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// The `f64` witness is a proof: a point inside the node where the
        /// exact sign is the one claimed, opposite to the ends'; none for a
        /// near miss; and a near hit that `f64` sees (`k ≤ 16`) is shown.
        #[test]
        fn float_witness_is_sound((d, n) in (2i64..51).prop_flat_map(|d| (Just(d), 1..d)), k in 8u64..60, hit in any::<bool>()) {
            let a = Rat::from_frac(n, d);
            let p = cluster(&a, k, hit);
            let (lo, hi) = dyadic_node(&a, 6);
            let eps = Rat::dyadic(Int::one(), k);
            prop_assume!(lo < &a - &eps && &a + &eps < hi);
            let iter = RootIter::new(SignProbe::shared(p.clone()), &lo, &hi);
            let node = Node::exact(&p, lo.clone(), hi.clone(), 0);
            let Some(SignSummary { first, .. }) = node.signs() else {
                return Ok(());
            };
            match iter.float_witness(&node, first) {
                Some((x, sign)) => {
                    prop_assert!(hit, "a witness of a near miss");
                    prop_assert!(lo < x && x < hi);
                    prop_assert_eq!(p.sign_at(&x), sign);
                    prop_assert!(sign != first);
                }
                None => prop_assert!(!hit || k > 16, "near hit at 2^-{} not shown", k),
            }
        }
    }

    /// A miss closer than the test reaches stays open (the isolation then
    /// zooms, as `clusters_far_below_bisection_depth` checks).
    #[test]
    fn a_miss_beyond_reach_stays_open() {
        // Complex roots 1/3 ± 2^(−1500)·i, in a node 1/8 wide.
        let p = cluster(&Rat::from_frac(1, 3), 1500, false);
        let (lo, hi) = (Rat::from_frac(1, 4), Rat::from_frac(3, 8));
        let (found, _) = exclusion(&p, &lo, &hi).expect("convex");
        assert!(matches!(found, Exclusion::Open));
    }

    /// The test's reach counts from the node's width: the same miss, 300
    /// bits inside a node of width `2^(−1200)`, is settled.
    #[test]
    fn reach_is_relative_to_the_node() {
        let a = Rat::from_frac(1, 3);
        let (lo, hi) = dyadic_node(&a, 1200);
        let (found, _) = exclusion(&cluster(&a, 1500, false), &lo, &hi).expect("convex");
        assert!(matches!(found, Exclusion::RootFree));
    }

    /// A miss whose bracket would jump past the cap gets one last round
    /// on the cap's grid: `1/3 ± 2^(−900)·i` (times `5t − 1`) in a node
    /// `2^(−10)` wide (brackets of 403 and 803 bits; the next grid, 1605 bits, is past
    /// the cap of 1034) is settled there.
    #[test]
    fn the_last_round_runs_on_the_cap() {
        let a = Rat::from_frac(1, 3);
        let (lo, hi) = dyadic_node(&a, 10);
        let fifth = ZPoly::from_i64s(&[-1, 5]);
        let (found, _) = exclusion(&(&cluster(&a, 900, false) * &fifth), &lo, &hi).expect("convex");
        assert!(matches!(found, Exclusion::RootFree));
    }

    /// The zoom's side tests decide in intervals where the margins allow
    /// (a first zoom into two roots `2^(−300)` apart: only the sub-interval
    /// is charged, no exact split), and exactly where they do not (the
    /// same zoom at speed 64 charges more than the sub-interval alone);
    /// both keep both roots.
    #[test]
    fn zoom_sides_in_intervals_then_exactly() {
        let a = Rat::from_frac(1, 3);
        let p = cluster(&a, 300, true);
        let (lo, hi) = dyadic_node(&a, 2);
        let (left, right) = (
            &a - &Rat::dyadic(Int::one(), 300),
            &a + &Rat::dyadic(Int::one(), 300),
        );
        for (speed, intervals) in [(2, true), (64, false)] {
            let mut iter = RootIter::new(SignProbe::shared(p.clone()), &lo, &hi);
            let mut node = Node::exact(&p, lo.clone(), hi.clone(), 0);
            node.cluster.speed = speed;
            let before = iter.work();
            let zoomed = iter.zoom(&mut node, 2).expect("the zoom holds");
            assert!(zoomed.lo < left && right < zoomed.hi);
            let Coeffs::Exact(b) = &zoomed.coeffs else {
                panic!("a zoom's sub-interval is exact");
            };
            let middle_only = before + exact_work(b, end_bits(b));
            assert_eq!(iter.work() == middle_only, intervals, "speed {speed}");
        }
    }

    fn summary(signs: &[i32]) -> Option<SignSummary> {
        SignSummary::of(signs.iter().map(|&s| Some(s)))
    }

    #[test]
    fn variations_skip_zeros() {
        let var = |signs: &[i32]| summary(signs).map(|s| s.var);
        assert_eq!(var(&[1, 0, -1, 0, 0, 1]), Some(2));
        assert_eq!(var(&[0, 0]), Some(0));
        assert_eq!(var(&[-1, -1, 1]), Some(1));
        let ends = summary(&[0, 1, -1, 0]).map(|s| (s.first, s.last));
        assert_eq!(ends, Some((0, 0)));
        assert_eq!(summary(&[]), None);
        assert_eq!(SignSummary::of([Some(1), None, Some(1)]), None);
    }
}
