//! The exact arithmetic's answers to Algorithm 1: every contact instant
//! isolated with exact rational bounds and every state decided by exact
//! signs.

use crate::geometry::Bodies;
use crate::signs::{model, ClosedForm, Coefficients};
use ccd_algorithm::{
    At, Candidates, CcdError, Decided, Found, Oracle, SignSet, Signs, Vanishing, VarSet,
};
use ccd_arith::{Int, Interval, Rat};
use ccd_classify::sign_variations;
use ccd_contact::Case;
use ccd_motion::{characteristic_at, placed_quadric, CharPoly};
use ccd_poly::ZPoly;
use ccd_scene::Scene;
use ccd_solver::{RealRoot, RootIter, SignModel};
use ccd_subres::{closed_forms, Quantity, QuarticInvariants};
use ccd_timeline::{Geometry, Instant, Path, State, Stats};
use std::cell::{Cell, OnceCell, RefCell};
use std::rc::Rc;

/// The largest closed form the exact path forms, in bits (degree times
/// coefficient length, [`exact_bits`]): 2²⁵, a polynomial of 4 MiB, about a
/// second of this machine's time to form and isolate (docs/termination.md).
pub const MAX_EXACT_BITS: u64 = 1 << 25;

/// The longest coefficient of `f` (bits) whose contents
/// [`CharPoly::without_constant_scalings`] takes before the size bound:
/// within twice the bound `f` then has at most 75 coefficients (degree 14)
/// at this length, each content a gcd of a few milliseconds, and shorter
/// coefficients cost less in all (more of them, each gcd quadratically
/// cheaper); a static pair of 10⁷-bit numbers would spend minutes.
const CONTENT_BITS: u64 = 1 << 17;

/// The placements' numbers (bits of both bodies, `PlacedQuadric::bits`)
/// up to which a first-contact query forms `f(λ; u)` of two bodies that
/// never turn before reading the state at `t0` off it.
const EARLY_F_BITS: u64 = 1024;

/// An upper estimate of the size in bits of `sr0`'s closed form: it is
/// homogeneous of degree 6 in the coefficients `f_k` of `f(λ; u)` (Section
/// 4), so it has degree `≤ 6·deg f` in `u` and coefficients of at most
/// about `6·τ` bits for `f_k` of `τ` bits (plus the binomial growth of the
/// products, a few bits per factor).
pub fn exact_bits(f: &CharPoly) -> u64 {
    let tau = f.coeffs.iter().map(ZPoly::max_bits).max().unwrap_or(0);
    let n = f.degree() as u64;
    (6 * n + 1) * (6 * tau + 8 * n.max(1))
}

/// The symbolic stage of a rational scene: the normalised `f(λ; u)` and its
/// five `sr` polynomials in `u = (t − t0)/(t1 − t0)`.
///
/// # Errors
///
/// [`CcdError::Motion`] when a motion degenerates on the span.
pub fn symbolic(scene: &Scene) -> Result<(CharPoly, QuarticInvariants<ZPoly>), CcdError> {
    let a = placed_quadric(&scene.a, &scene.span).map_err(|e| CcdError::motion("a", e))?;
    let b = placed_quadric(&scene.b, &scene.span).map_err(|e| CcdError::motion("b", e))?;
    let f = CharPoly::from_placed(&a, &b);
    let inv = closed_forms(&f.coeffs);
    Ok((f, inv))
}

/// The narrowing, in bits of the parameter, past which the signs at a
/// root give way to the other certificates of the touch test (the states
/// on both sides, a point of both interiors; [`RealRoot::sign_within`]
/// stops once its enclosure is narrower, so the last round may have
/// narrowed further): the signs at the roots of every stability scene but
/// one are decided on enclosures of at most 73 bits;
/// `ratio-needle-k0064-overlap`'s need 1,072–1,093.
const CHEAP_SIGN_BITS: i64 = 128;

/// A candidate of the exact path: a real root of `sr0` (or `sr11`) with
/// exact rational bounds — from the filter (its model is `sr0`'s closed
/// form over `f`'s coefficients) or from the exact isolation of the formed
/// polynomial — and the signs proven at it so far.
pub struct ExactRoot {
    isolation: Isolation,
    /// Signs proven at the root, each asked once: the touch test asks
    /// `sr11`, and the case of the contact geometry after it reads
    /// whether `sr11` vanishes from it (or, unknown, from the zero test
    /// alone).
    known: Vec<(Quantity, i32)>,
}

/// Where an [`ExactRoot`] comes from.
enum Isolation {
    /// A root the filter isolated.
    Filtered(RealRoot<ClosedForm>),
    /// A root of the formed polynomial's squarefree part.
    Isolated(RealRoot),
}

/// `$body` with `$r` bound to the root inside either variant.
macro_rules! each {
    ($root:expr, $r:ident => $body:expr) => {
        match $root {
            Isolation::Filtered($r) => $body,
            Isolation::Isolated($r) => $body,
        }
    };
}

impl ExactRoot {
    fn filtered(r: RealRoot<ClosedForm>) -> ExactRoot {
        ExactRoot::of(Isolation::Filtered(r))
    }
    fn isolated(r: RealRoot) -> ExactRoot {
        ExactRoot::of(Isolation::Isolated(r))
    }
    fn of(isolation: Isolation) -> ExactRoot {
        ExactRoot {
            isolation,
            known: Vec::new(),
        }
    }
    fn ends(&self) -> (Rat, Rat) {
        each!(&self.isolation, r => (r.lo().clone(), r.hi().clone()))
    }
    /// The sign of `q` at the root ([`RealRoot::sign_within`]: `None`
    /// where it is not decided on an enclosure of `2^−max_bits`), proven
    /// once.
    fn sign(
        &mut self,
        q: Quantity,
        coefficients: &Rc<Coefficients>,
        max_bits: Option<i64>,
    ) -> Option<i32> {
        if let Some(s) = self.known(q) {
            return Some(s);
        }
        let m = model(coefficients, q);
        let s = each!(&mut self.isolation, r => r.sign_within(&m, max_bits))?;
        self.known.push((q, s));
        Some(s)
    }
    /// Whether `q` vanishes at the root: its sign when known, else the
    /// zero test alone ([`RealRoot::vanishes_with`]).
    fn vanishes(&self, q: Quantity, coefficients: &Rc<Coefficients>) -> bool {
        match self.known(q) {
            Some(s) => s == 0,
            None => each!(&self.isolation, r => r.vanishes_with(&model(coefficients, q))),
        }
    }
    /// The sign of `q` proven at the root so far.
    fn known(&self, q: Quantity) -> Option<i32> {
        self.known.iter().find(|(k, _)| *k == q).map(|&(_, s)| s)
    }
}

/// A sample point: enclosures of `f`'s coefficients there and the closed
/// forms over them (`f64` intervals, a filter) and, once one of those does
/// not exclude zero, the exact coefficients and closed forms.
struct Sample {
    at: Rat,
    /// `f`'s coefficients at `at` up to one positive factor and a positive
    /// rescaling of `λ` (which keep every sign Theorem 3.10 reads: the
    /// closed forms are homogeneous and isobaric), enclosed.
    coefficients: [Interval; 5],
    filter: QuarticInvariants<Interval>,
    /// The exact coefficients (times a positive factor), once needed.
    values: Option<[Int; 5]>,
    exact: Option<QuarticInvariants<Int>>,
}

impl Sample {
    /// From the exact coefficients.
    fn new(at: Rat, values: [Int; 5]) -> Sample {
        // One common power of two (the closed forms are homogeneous) puts
        // the largest coefficient near 2^64: no overflow in products of six.
        let bits = values.iter().map(Int::bits).max().unwrap_or(0) as i64;
        let scaled = values
            .each_ref()
            .map(|v| Interval::from_int_scaled(v, bits - 64));
        Sample {
            values: Some(values),
            ..Sample::enclosed(at, scaled)
        }
    }

    /// From enclosures of the coefficients (the set-up `f`'s views,
    /// [`Coefficients::views_at`]); the exact ones are formed only where
    /// the enclosures do not decide.
    fn enclosed(at: Rat, coefficients: [Interval; 5]) -> Sample {
        Sample {
            at,
            filter: closed_forms(&coefficients),
            coefficients,
            values: None,
            exact: None,
        }
    }

    /// The sign of `q` here: from the enclosure when it excludes zero
    /// (proven), else `0` when `q` is proven identically zero on the span
    /// (`known_zero`: its enclosure holds that 0, and the exact closed
    /// forms would be formed only to read it), else from the exact closed
    /// form (of the exact coefficients `values` gives).
    fn sign(
        &mut self,
        q: Quantity,
        known_zero: impl FnOnce() -> bool,
        values: impl FnOnce() -> [Int; 5],
    ) -> i32 {
        if let Some(s) = self
            .filter
            .get(q)
            .and_then(Interval::sign)
            .filter(|s| *s != 0)
        {
            return s;
        }
        if known_zero() {
            return 0;
        }
        let Sample {
            values: v, exact, ..
        } = self;
        let exact = exact.get_or_insert_with(|| closed_forms(v.get_or_insert_with(values)));
        exact.get(q).map_or(0, Int::signum)
    }

    /// `Var` of the coefficients: from their enclosures when each is
    /// signed (a point `[0, 0]` encloses exactly `0`), else exactly.
    fn variations(&mut self, values: impl FnOnce() -> [Int; 5]) -> usize {
        let signs: Option<Vec<i32>> = self.coefficients.iter().map(Interval::sign).collect();
        match signs {
            Some(signs) => sign_variations(&signs),
            None => sign_variations(
                &self
                    .values
                    .get_or_insert_with(values)
                    .each_ref()
                    .map(Int::signum),
            ),
        }
    }
}

/// The exact arithmetic over a rational scene, in `u ∈ [0, 1]`.
pub struct Exact<'s> {
    scene: &'s Scene,
    digits: u32,
    /// The placements and what the contact geometry needs, formed in
    /// [`Exact::new`] (which validates the motions) or, for a static pair,
    /// only when a contact's geometry is asked for.
    bodies: OnceCell<Bodies<'s>>,
    unit: [Rat; 2],
    /// `10^−digits`, the width of a reported enclosure in `u`.
    width: Rat,
    /// `f(λ; u)` and its sign models, once [`Oracle::prepare`] ran.
    f: Option<Rc<Coefficients>>,
    /// `sr0` (or `sr11`) was formed as a polynomial.
    formed: Cell<bool>,
    /// `sr0(1/2) ≠ 0` by the `f64` filter: its roots may come from the
    /// filter alone.
    filtered: bool,
    /// `sr11(1/2) ≠ 0` by the `f64` filter where `sr0 ≡ 0` (asked only
    /// then): its roots may come from the filter alone.
    filtered11: bool,
    /// The last sample's closed forms and coefficient signs.
    sample: RefCell<Option<Sample>>,
    /// `f(λ; u)` formed before [`Oracle::prepare`] to read a sample off it,
    /// when that is cheaper than the placements (bodies that never turn),
    /// and from the start for a static pair.
    early: RefCell<Option<CharPoly>>,
}

/// The placements of both bodies (validated exactly on the span).
fn placed_bodies(scene: &Scene, digits: u32) -> Result<Bodies<'_>, CcdError> {
    let a = placed_quadric(&scene.a, &scene.span).map_err(|e| CcdError::motion("a", e))?;
    let b = placed_quadric(&scene.b, &scene.span).map_err(|e| CcdError::motion("b", e))?;
    Ok(Bodies::new(scene, a, b, digits))
}

impl<'s> Exact<'s> {
    /// The placements of both bodies (validated exactly on the span); for
    /// a static pair `f(λ)` straight from the scene instead
    /// ([`CharPoly::of_static`]: the same polynomial), the placements left
    /// until a contact's geometry needs them.
    ///
    /// # Errors
    ///
    /// [`CcdError::Motion`] when a motion degenerates on the span.
    pub fn new(scene: &'s Scene, digits: u32) -> Result<Exact<'s>, CcdError> {
        let f = CharPoly::of_static(&scene.a, &scene.b);
        Exact::with(scene, digits, f)
    }

    /// [`Exact::new`] with `f` formed in advance (a static pair) or not.
    fn with(scene: &'s Scene, digits: u32, f: Option<CharPoly>) -> Result<Exact<'s>, CcdError> {
        let bodies = match f {
            Some(_) => OnceCell::new(),
            None => OnceCell::from(placed_bodies(scene, digits)?),
        };
        Ok(Exact {
            scene,
            digits,
            bodies,
            unit: [Rat::zero(), Rat::one()],
            width: Rat::new(Int::one(), Int::pow10(digits)).expect("nonzero denominator"),
            f: None,
            formed: Cell::new(false),
            filtered: false,
            filtered11: false,
            sample: RefCell::new(None),
            early: RefCell::new(f),
        })
    }

    /// The placements (formed on first need for a static pair, whose
    /// placement [`Exact::new`] skipped: `placed_quadric` has no error case
    /// for a static body, whose frame is constant).
    fn bodies(&self) -> &Bodies<'s> {
        self.bodies.get_or_init(|| {
            placed_bodies(self.scene, self.digits)
                .expect("a static body's placement has no error case")
        })
    }

    fn coefficients(&self) -> &Rc<Coefficients> {
        self.f
            .as_ref()
            .expect("f(λ; u) is set up before roots are asked for")
    }

    /// The coefficients of `f(λ; u)` at `u` (times a positive factor), from
    /// `f` once it is set up. Before (the state at `t0` of a first-contact
    /// query): from `f` formed early when both bodies never turn and their
    /// numbers are short (then `f` costs less than the placements' quadrics
    /// and [`Oracle::prepare`] reuses it), else straight from the placements
    /// (long numbers: `f` may cost seconds, and the query may stop at `t0`).
    fn values_at(&self, u: &Rat) -> [Int; 5] {
        if let Some(f) = &self.f {
            return f.char_poly().at_scaled(u);
        }
        let mut early = self.early.borrow_mut();
        if early.is_none() {
            let (a, b) = (&self.bodies().a, &self.bodies().b);
            if !(a.turns() || b.turns()) && a.bits() + b.bits() <= EARLY_F_BITS {
                *early = Some(self.char_poly());
            }
        }
        match &*early {
            Some(f) => f.at_scaled(u),
            None => characteristic_at(&self.bodies().a, &self.bodies().b, u),
        }
    }

    /// `f(λ; u)` of the placements ([`CharPoly::from_placed`]).
    fn char_poly(&self) -> CharPoly {
        CharPoly::from_placed(&self.bodies().a, &self.bodies().b)
    }

    /// Whether `q` is proven identically zero on the span, once `f` is set
    /// up: as Algorithm 1's plan found it, or, for `sr0` before the plan
    /// asks (the state at `t0` of a full query), decided here as the plan
    /// will decide it next ([`Coefficients::vanishes_identically`], once),
    /// unless the filter proved `sr0(1/2) ≠ 0` (then the plan does not ask).
    fn zero_on_span(&self, q: Quantity) -> bool {
        let Some(f) = &self.f else {
            return false;
        };
        // (`Var` is no closed form: never zero on the span.)
        q != Quantity::Var
            && (f.proven_zero(q)
                || (q == Quantity::Sr0 && !self.filtered && f.vanishes_identically(q)))
    }

    /// `deg sr0` (`None` when `sr0 ≡ 0`) without forming `sr0`: `0` for a
    /// constant `f` (a static pair) whose `sr0` the filter proved nonzero,
    /// else [`Coefficients::sr0_degree`].
    fn sr0_degree(&self, f: &Coefficients) -> Option<usize> {
        if self.filtered && f.char_poly().degree() == 0 {
            Some(0)
        } else {
            f.degree(Quantity::Sr0)
        }
    }
}

/// Exact signs at a rational sample (closed forms of the coefficients
/// there, computed once per sample).
struct SampleSigns<'a, 's>(&'a Exact<'s>, Rat);

impl SampleSigns<'_, '_> {
    /// The sample at this point, cached: once `f` is set up, from its
    /// views' enclosures (interval Horner, no exact evaluation unless they
    /// do not decide), before that from the exact coefficients.
    fn with<T>(&self, read: impl FnOnce(&mut Sample) -> T) -> T {
        let mut cache = self.0.sample.borrow_mut();
        if cache.as_ref().is_none_or(|s| s.at != self.1) {
            *cache = Some(match &self.0.f {
                Some(f) => Sample::enclosed(self.1.clone(), f.views_at(&self.1)),
                None => Sample::new(self.1.clone(), self.0.values_at(&self.1)),
            });
        }
        read(cache.as_mut().expect("just filled"))
    }
}

impl Signs for SampleSigns<'_, '_> {
    fn sign(&mut self, q: Quantity) -> SignSet {
        SignSet::exactly(
            self.with(|s| s.sign(q, || self.0.zero_on_span(q), || self.0.values_at(&self.1))),
        )
    }
    fn variations(&mut self) -> VarSet {
        VarSet::exactly(self.with(|s| s.variations(|| self.0.values_at(&self.1))))
    }
}

/// Exact signs at an algebraic root ([`RealRoot::sign_within`]), within
/// a bound on the root's narrowing (`None`: none); a sign not decided
/// within it reads as unknown.
struct RootSigns<'a>(&'a mut ExactRoot, &'a Rc<Coefficients>, Option<i64>);

impl Signs for RootSigns<'_> {
    fn sign(&mut self, q: Quantity) -> SignSet {
        self.0
            .sign(q, self.1, self.2)
            .map_or(SignSet::ANY, SignSet::exactly)
    }
    /// Never asked: the touch test stops before `Var`.
    fn variations(&mut self) -> VarSet {
        VarSet::default()
    }
}

/// Whether `sr11`'s roots (where `sr0 ≡ 0`) may come from the filter
/// alone, as `sr0`'s do: `f` is not constant (a constant `f`'s `sr11` is
/// one closed form of integers), its numbers are long (short ones form
/// `sr11` in `i128` for less, and the explicit polynomial refines a root
/// for half the closed form's cost), the filter proves `sr11(1/2) ≠ 0`,
/// and the filter can expect to decide ([`RootIter::filter_may_decide`]).
fn sr11_filter_first(f: &Rc<Coefficients>) -> bool {
    if f.char_poly().degree() == 0 || f.short(Quantity::Sr11) {
        return false;
    }
    let m = model(f, Quantity::Sr11);
    m.filtered_sign_at(&Rat::from_frac(1, 2)) != 0
        && RootIter::filter_may_decide(&m, &Rat::zero(), &Rat::one())
}

/// The first of 1/2, 1/4, 3/4, 1/8, 3/8, … that is not a root of `p ≠ 0`.
fn non_root_dyadic(p: &ZPoly) -> Rat {
    (1u64..)
        .flat_map(|k| {
            (1..(1u64 << k.min(62)))
                .step_by(2)
                .map(move |m| Rat::dyadic(Int::from_u64(m), k))
        })
        .find(|d| p.sign_at(d) != 0)
        .expect("a nonzero polynomial has finitely many roots")
}

/// Roots of an exact isolation, ending in the effort bound's error or the
/// filter's giving up.
fn stream<M: ccd_solver::SignModel + Clone>(
    mut roots: RootIter<M>,
    wrap: fn(RealRoot<M>) -> ExactRoot,
) -> impl Iterator<Item = Found<ExactRoot>> {
    let mut done = false;
    std::iter::from_fn(move || {
        if done {
            return None;
        }
        if let Some(r) = roots.next() {
            return Some(Found::Root(wrap(r)));
        }
        done = true;
        if roots.exhausted() {
            Some(Found::Failed(CcdError::Effort {
                limit: "exact work",
                unit: "word operations of exact root isolation",
                bound: ccd_solver::MAX_EXACT_WORK,
                reached: roots.work(),
            }))
        } else if roots.undecided() {
            Some(Found::GaveUp)
        } else {
            None
        }
    })
}

impl Oracle for Exact<'_> {
    type Root = ExactRoot;
    const PATH: Path = Path::Exact;
    const SAMPLE_AT_ENDS: bool = true;
    /// Level 0: the signs at a root within `CHEAP_SIGN_BITS` (128); level 1:
    /// without a bound, after the other certificates.
    const LEVELS: usize = 2;
    const CERTIFICATES_BEFORE_LEVEL: Option<usize> = Some(1);

    fn domain(&self) -> &[Rat; 2] {
        &self.unit
    }

    /// `t0 + u·(t1 − t0)`.
    fn time(&self, u: &Rat) -> Rat {
        ccd_algorithm::time_on(&self.scene.span, u)
    }

    fn signs<'a>(&'a self, at: At<'a, ExactRoot>, level: usize) -> Box<dyn Signs + 'a> {
        match at {
            At::Sample(u) => Box::new(SampleSigns(self, u.clone())),
            At::Root(r) => {
                let bound = (level == 0).then_some(CHEAP_SIGN_BITS);
                Box::new(RootSigns(r, self.coefficients(), bound))
            }
        }
    }

    fn guess(&self, _u: &Rat) -> State {
        unreachable!("exact signs decide every sample")
    }

    /// Forms `f(λ; u)`, refusing a closed form above [`MAX_EXACT_BITS`]
    /// (after [`CharPoly::without_constant_scalings`] when it is up to
    /// twice that long).
    fn prepare(&mut self) -> Result<(), CcdError> {
        let mut f = self
            .early
            .borrow_mut()
            .take()
            .unwrap_or_else(|| self.char_poly());
        let mut size = exact_bits(&f);
        let longest = f.coeffs.iter().map(ZPoly::max_bits).max().unwrap_or(0);
        if size > MAX_EXACT_BITS && size <= 2 * MAX_EXACT_BITS && longest <= CONTENT_BITS {
            // Long constant factors left in f (a positive rescaling of λ
            // and f: the sample read before stays valid, as below). Only
            // near the bound: the contents' gcds grow with f, and past
            // twice the bound they did not bring it back (rigid-288
            // perturbed at the 1000th digit: 150M bits → 81M, 6 s more).
            f = f.without_constant_scalings();
            size = exact_bits(&f);
        }
        if size > MAX_EXACT_BITS {
            return Err(CcdError::Effort {
                limit: "exact size",
                unit: "bits in the closed form of sr0",
                bound: MAX_EXACT_BITS,
                reached: size,
            });
        }
        let f = Rc::new(Coefficients::new(f));
        // A sample read before (the state at t0 of a first-contact query)
        // stays valid: its values are those of f there up to a positive
        // factor and a positive rescaling of λ (the early f is this f; the
        // placements' quadrics are positive multiples of A and B), which
        // keep every sign it answers (Theorem 3.10's signs, the
        // normalisation's invariants; `characteristic` module docs).
        // sr0's roots from its certified f64 Bernstein coefficients when
        // the filter proves sr0(1/2) ≠ 0 (crate::signs); otherwise sr0 is
        // formed.
        self.filtered = model(&f, Quantity::Sr0).filtered_sign_at(&Rat::from_frac(1, 2)) != 0;
        self.f = Some(f);
        Ok(())
    }

    fn vanishes(&mut self, q: Quantity) -> Vanishing {
        if q == Quantity::Sr0 && self.filtered {
            return Vanishing::Not(None);
        }
        let f = Rc::clone(self.coefficients());
        if q == Quantity::Sr11 && sr11_filter_first(&f) {
            // sr11 ≢ 0, and 1/2 is the non-root Theorem 5.5 reads.
            self.filtered11 = true;
            return Vanishing::Not(Some(Rat::from_frac(1, 2)));
        }
        let zero = f.vanishes_identically(q);
        // sr0 proven zero by a fixed repeated factor is not formed.
        if f.formed(q) {
            self.formed.set(true);
        }
        if zero {
            return Vanishing::Identically;
        }
        let p = f.polynomial(q);
        if q == Quantity::Sr11 {
            Vanishing::Not(Some(non_root_dyadic(p)))
        } else {
            Vanishing::Not(None)
        }
    }

    /// The filter's roots first (attempt 0, when it applies), then the
    /// exact isolation of the formed polynomial.
    fn candidates(&self, q: Quantity, attempt: usize) -> Option<Candidates<'_, ExactRoot>> {
        let f = self.coefficients();
        let (zero, one) = (Rat::zero(), Rat::one());
        let filtered = match q {
            Quantity::Sr0 => self.filtered,
            Quantity::Sr11 => self.filtered11,
            _ => false,
        };
        if filtered && attempt == 0 {
            // A constant f (a static pair): sr0 is the constant the filter
            // proved nonzero at 1/2, so it has no roots.
            if f.char_poly().degree() == 0 {
                return Some(Candidates {
                    degree: self.sr0_degree(f),
                    roots: Box::new(std::iter::empty()),
                });
            }
            let bernstein = crate::filter::certified_bernstein(f.char_poly(), q);
            let roots = RootIter::filtered(model(f, q), &zero, &one, &bernstein);
            return Some(Candidates {
                degree: f.degree(q),
                roots: Box::new(stream(roots, ExactRoot::filtered)),
            });
        }
        if attempt > usize::from(filtered) {
            return None;
        }
        self.formed.set(true);
        let poly = f.polynomial(q);
        let square = (q == Quantity::Sr11)
            .then(|| f.triple_root_instants())
            .flatten();
        let roots = ccd_solver::isolate_with(poly, square.as_ref(), &zero, &one).ok()?;
        Some(Candidates {
            degree: poly.degree(),
            roots: Box::new(stream(roots, ExactRoot::isolated)),
        })
    }

    fn ends(&self, r: &ExactRoot) -> (Rat, Rat) {
        r.ends()
    }

    /// A point of both interiors throughout the root's enclosure, in
    /// time ([`ccd_contact::interiors_meet`], in `f64` intervals).
    fn interiors_meet(&self, r: &ExactRoot) -> bool {
        // `t0 < t1` (a scene invariant), so the times keep their order.
        let (lo, hi) = r.ends();
        let (lo, hi) = (self.time(&lo), self.time(&hi));
        let bodies = (&self.scene.a, &self.scene.b, &self.scene.span);
        ccd_contact::interiors_meet::<Interval>(bodies, (&lo, &hi), 53)
    }

    fn refine(&self, r: &mut ExactRoot, _q: Quantity) -> Instant {
        each!(&mut r.isolation, x => x.refine_to(&self.width));
        let (lo, hi) = r.ends();
        Instant {
            lo,
            hi,
            certified: true,
        }
    }

    fn geometry(&self, r: &mut ExactRoot, zeros: &[Quantity], _instant: &Instant) -> Geometry {
        // The case of Theorem 3.10(2): whether sr11 vanishes at the root —
        // its sign when the touch test proved it, else the zero test alone
        // (a touch proven by the states on both sides).
        let simple =
            !zeros.contains(&Quantity::Sr11) && !r.vanishes(Quantity::Sr11, self.coefficients());
        let case = if simple {
            Case::Simple
        } else {
            Case::TwoDouble
        };
        each!(&mut r.isolation, x => self.bodies().exact(x, case))
    }

    fn geometry_at(&self, u: &Rat, _zeros: &[Quantity]) -> Geometry {
        self.bodies().at_touch(u)
    }

    fn touch_between_contacts(&self, u: &Rat, _d: Decided) -> Result<Decided, CcdError> {
        Err(CcdError::Internal(format!(
            "touch at sample u = {u} between contacts"
        )))
    }

    fn stats(&self, stats: &mut Stats) {
        let Some(f) = &self.f else { return };
        stats.deg_f = f.char_poly().degree();
        stats.sr0_formed = self.formed.get();
        stats.deg_sr0 = if f.proven_zero(Quantity::Sr0) {
            None
        } else if self.formed.get() {
            f.polynomial(Quantity::Sr0).degree()
        } else {
            self.sr0_degree(f)
        };
    }
}

#[cfg(test)]
mod tests {
    use super::{Exact, Sample};
    use crate::signs::Coefficients;
    use ccd_algorithm::Options;
    use ccd_arith::{Int, Rat};
    use ccd_motion::{placed_quadric, Bezier, Body, CharPoly, Motion, Quat, Vec3};
    use ccd_quadric::{characteristic, norm2, rotation_numerator};
    use ccd_scene::Scene;
    use ccd_subres::{closed_forms, Quantity};

    /// Every sign a sample answers.
    fn sample_signs(at: &Rat, values: [Int; 5]) -> Vec<i32> {
        let mut s = Sample::new(at.clone(), values.clone());
        let mut out: Vec<i32> = QUANTITIES
            .into_iter()
            .map(|q| s.sign(q, || false, || unreachable!("given")))
            .collect();
        out.extend(values.iter().map(Int::signum));
        out
    }

    /// The closed forms a sample answers.
    const QUANTITIES: [Quantity; 5] = [
        Quantity::Sr22,
        Quantity::Sr20,
        Quantity::Sr11,
        Quantity::Sr10,
        Quantity::Sr0,
    ];

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
        /// A sample read off the placements' quadrics (a first-contact
        /// query's state at t0 before the set-up) answers every sign as
        /// the set-up `f` does at the same point, so `prepare` keeps it:
        /// random static or translating pairs of every orientation, long
        /// decimal numbers, samples at the ends and inside the span, and
        /// grazing pairs (B's centre passing at distance r_A + r_B of A's
        /// for spheres).
        #[test]
        fn placements_sample_has_the_signs_of_f(
            quats in proptest::collection::vec(-9i64..10, 8),
            radii in proptest::collection::vec((1i64..5000, 0u32..4), 6),
            points in proptest::collection::vec((-100_000i64..100_000, 0u32..5), 9),
            at in (0i64..9, 1i64..9),
            graze in proptest::bool::ANY,
        ) {
            let dec = |(n, e): (i64, u32)| Rat::from_frac(n, 10i64.pow(e));
            let quat = |k: usize| {
                let mut q: [Rat; 4] = std::array::from_fn(|i| Rat::from(quats[4 * k + i]));
                if q.iter().all(Rat::is_zero) {
                    q[0] = Rat::one();
                }
                q
            };
            let radius = |k: usize| -> [Rat; 3] {
                std::array::from_fn(|i| {
                    let r = dec(radii[3 * k + i]);
                    if graze { dec(radii[0]) } else { r }
                })
            };
            let point = |p: usize| -> [Rat; 3] { std::array::from_fn(|i| dec(points[3 * p + i])) };
            let a = Body { radii: radius(0), motion: Motion::Static { center: point(0), orientation: quat(0) } };
            let mut end = point(2);
            if graze {
                // B ends where two equal spheres touch.
                end = [&point(0)[0] + &(&dec(radii[0]) * &Rat::from(2)), point(0)[1].clone(), point(0)[2].clone()];
            }
            let b = Body {
                radii: radius(1),
                motion: Motion::Translation {
                    center: Bezier { points: vec![point(1), end], weights: None },
                    orientation: quat(1),
                },
            };
            let span = [Rat::zero(), Rat::one()];
            let (pa, pb) = (placed_quadric(&a, &span).unwrap(), placed_quadric(&b, &span).unwrap());
            let f = CharPoly::from_placed(&pa, &pb);
            let u = Rat::from_frac(at.0.min(at.1), at.1);
            let coefficients = Coefficients::new(f.clone());
            for u in [Rat::zero(), Rat::one(), u] {
                let direct = characteristic(&pa.quadric_at(&u), &pb.quadric_at(&u));
                let exact = f.at_scaled(&u);
                proptest::prop_assert_eq!(sample_signs(&u, direct), sample_signs(&u, exact.clone()), "at {}", u);
                // The set-up f's views (a sample after `prepare`) give the
                // same signs and the same Var (with the exact values to
                // fall back on where their enclosures do not decide).
                let mut by_views = Sample::enclosed(u.clone(), coefficients.views_at(&u));
                let mut by_values = Sample::new(u.clone(), exact.clone());
                for q in QUANTITIES {
                    let want = by_values.sign(q, || false, || unreachable!("given"));
                    proptest::prop_assert_eq!(by_views.sign(q, || false, || exact.clone()), want, "{:?} at {}", q, u);
                }
                let want = by_values.variations(|| unreachable!("given"));
                proptest::prop_assert_eq!(by_views.variations(|| exact.clone()), want, "Var at {}", u);
            }
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]
        /// Where `sr0 ≡ 0` (two spheres, one translating past the other;
        /// the same for equal spheres whose path grazes, a double root of
        /// `sr11`), `sr11`'s roots from the `f64` filter (attempt 0), when
        /// it decides them all, are the exact isolation's (attempt 1): as
        /// many, in order, each refined enclosure meeting its partner's.
        /// The filter answers on some cases and gives up on others. The
        /// numbers are long (the filter's domain: short ones form `sr11`
        /// in `i128`): radii and positions carry `1 + 10^(−12)`-like
        /// factors.
        #[test]
        fn sr11_filter_roots_are_the_exact_roots(
            radii in (1i64..9, 1i64..9),
            points in proptest::collection::vec(-40i64..40, 6),
            den in 1i64..9,
            graze in 0i64..3,
            nudge in 1i64..1000,
        ) {
            let long = Rat::new(Int::pow10(12) + Int::from(nudge), Int::pow10(12)).expect("nonzero");
            let rat = |n: i64| &Rat::from_frac(n, den) * &long;
            let ra = &Rat::from(radii.0) * &long;
            let rb = if graze > 0 { ra.clone() } else { Rat::from(radii.1) };
            let one = [Rat::one(), Rat::zero(), Rat::zero(), Rat::zero()];
            let (start, end): ([Rat; 3], [Rat; 3]) = if graze > 0 {
                // Along x at the height ra + rb (graze 1: a touch at
                // t = 10/21, off the filter's sample 1/2) or a little
                // below it (graze 2: an overlap).
                let h = &(&ra + &rb) - &Rat::from_frac(graze - 1, 1000);
                ([Rat::from(-10), h.clone(), Rat::zero()], [Rat::from(11), h, Rat::zero()])
            } else {
                (std::array::from_fn(|i| rat(points[i])), std::array::from_fn(|i| rat(points[3 + i])))
            };
            sr11_roots_agree(start, end, &ra, &rb, &one)?;
        }
    }

    /// Body `a` static at the origin, `b` translating from `start` to
    /// `end` over `[0, 1]`, each with its radii and orientation.
    fn passing(
        (ra, qa): ([Rat; 3], Quat),
        (rb, qb): ([Rat; 3], Quat),
        start: [Rat; 3],
        end: [Rat; 3],
    ) -> Scene {
        let a = Body {
            radii: ra,
            motion: Motion::Static {
                center: [Rat::zero(), Rat::zero(), Rat::zero()],
                orientation: qa,
            },
        };
        let b = Body {
            radii: rb,
            motion: Motion::Translation {
                center: Bezier {
                    points: vec![start, end],
                    weights: None,
                },
                orientation: qb,
            },
        };
        Scene {
            span: [Rat::zero(), Rat::one()],
            a,
            b,
        }
    }

    /// A body of radius 1 passing through one of radius 2: spheres
    /// (`sr0 ≡ 0`), or ellipsoids of those scales (`sr0` proven nonzero by
    /// the filter).
    fn passing_through(spheres: bool) -> Scene {
        let radii = |r: i64| {
            if spheres {
                [Rat::from(r), Rat::from(r), Rat::from(r)]
            } else {
                [Rat::from(r), Rat::from(3 * r), Rat::from_frac(r, 2)]
            }
        };
        let one = [Rat::one(), Rat::zero(), Rat::zero(), Rat::zero()];
        let turned = [Rat::from(2), Rat::one(), Rat::zero(), Rat::one()];
        passing(
            (radii(2), one),
            (radii(1), turned),
            [Rat::from(-5), Rat::from_frac(1, 3), Rat::zero()],
            [Rat::from(6), Rat::from_frac(1, 3), Rat::zero()],
        )
    }

    /// Where `sr0 ≡ 0` (spheres), a sample reads `sr0 = 0` without the
    /// exact closed forms: at the first sample before the plan has asked
    /// (decided on the spot, as for the state at `t0` of a full query),
    /// and after. Every sign is the exact closed forms' of the sample's
    /// values. Asking about `sr11` forms nothing, and where the filter
    /// proved `sr0(1/2) ≠ 0` (ellipsoids) asking about `sr0` forms nothing
    /// either: the plan would not ask.
    #[test]
    fn samples_read_a_vanishing_quantity_without_the_exact_forms() {
        use ccd_algorithm::{At, Oracle, SignSet, Vanishing};
        let scene = passing_through(true);
        let mut o = Exact::new(&scene, 12).expect("a translation");
        o.prepare().expect("short numbers");
        let quantities = QUANTITIES;
        for (i, x) in [1, 2, 5, 9]
            .map(|k| Rat::from_frac(k, 10))
            .iter()
            .enumerate()
        {
            if i == 2 {
                assert!(matches!(o.vanishes(Quantity::Sr0), Vanishing::Identically));
            }
            let ours = quantities.map(|q| o.signs(At::Sample(x), 0).sign(q));
            let exact = closed_forms(&o.values_at(x));
            let want = quantities.map(|q| SignSet::exactly(exact.get(q).map_or(0, Int::signum)));
            assert_eq!(ours, want, "at {x}");
            assert_eq!(ours[4], SignSet::exactly(0), "at {x}");
            let formed = o
                .sample
                .borrow()
                .as_ref()
                .is_some_and(|s| s.exact.is_some());
            assert!(!formed, "at {x}");
        }
        assert!(!o.zero_on_span(Quantity::Sr11));
        assert!(!o.coefficients().formed(Quantity::Sr11));

        let scene = passing_through(false);
        let mut o = Exact::new(&scene, 12).expect("a translation");
        o.prepare().expect("short numbers");
        assert!(o.filtered, "the filter proves sr0(1/2) ≠ 0");
        assert!(!o.zero_on_span(Quantity::Sr0));
        assert!(!o.coefficients().formed(Quantity::Sr0));
    }

    /// The filter does answer `sr11`'s roots (what the proptest above
    /// compares is not vacuous): a long-number sphere passing through a
    /// larger one, two simple roots.
    #[test]
    fn sr11_filter_answers_an_overlap_of_spheres() {
        let long = Rat::new(Int::pow10(12) + Int::from(7), Int::pow10(12)).expect("nonzero");
        let one = [Rat::one(), Rat::zero(), Rat::zero(), Rat::zero()];
        let y = &Rat::from_frac(7, 5) * &long;
        let start = [Rat::from(-3), y.clone(), Rat::zero()];
        let end = [Rat::from(4), y, Rat::zero()];
        let compared = sr11_roots_agree(start, end, &Rat::one(), &Rat::from_frac(1, 2), &one)
            .expect("the roots agree");
        assert_eq!(compared, Some(2));
    }

    /// [`sr11_filter_roots_are_the_exact_roots`] on one pair of spheres:
    /// the number of roots compared, `None` when the filter did not
    /// answer (not taken, or gave up).
    fn sr11_roots_agree(
        start: [Rat; 3],
        end: [Rat; 3],
        ra: &Rat,
        rb: &Rat,
        q: &Quat,
    ) -> Result<Option<usize>, proptest::test_runner::TestCaseError> {
        use ccd_algorithm::{Found, Oracle, Vanishing};
        let sphere = |r: &Rat| [r.clone(), r.clone(), r.clone()];
        let scene = passing((sphere(ra), q.clone()), (sphere(rb), q.clone()), start, end);
        let mut o = Exact::new(&scene, 12).expect("a translation");
        o.prepare().expect("short numbers");
        proptest::prop_assert!(matches!(o.vanishes(Quantity::Sr0), Vanishing::Identically));
        if !matches!(o.vanishes(Quantity::Sr11), Vanishing::Not(_)) {
            return Ok(None);
        }
        let roots = |attempt: usize| -> Option<Vec<ccd_timeline::Instant>> {
            let c = o.candidates(Quantity::Sr11, attempt)?;
            let mut found = Vec::new();
            for r in c.roots {
                match r {
                    Found::Root(mut r) => found.push(o.refine(&mut r, Quantity::Sr11)),
                    _ => return None,
                }
            }
            Some(found)
        };
        let (Some(filtered), Some(exact)) = (roots(0), roots(1)) else {
            return Ok(None);
        };
        proptest::prop_assert_eq!(filtered.len(), exact.len());
        for (x, y) in filtered.iter().zip(&exact) {
            proptest::prop_assert!(x.lo <= y.hi && y.lo <= x.hi, "{:?} vs {:?}", x, y);
        }
        Ok(Some(filtered.len()))
    }

    /// `R(q)·v = M(q)·v / |q|²`.
    fn rotate(q: &Quat, v: &Vec3) -> Vec3 {
        let (m, n) = (rotation_numerator(q), norm2(q));
        std::array::from_fn(|i| {
            let s = (0..3).fold(Rat::zero(), |s, j| &s + &(&m[i][j] * &v[j]));
            &s / &n
        })
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(96))]
        /// A static pair gets the very outcome from the lean route (`f`
        /// straight from the scene, no placements until a contact's
        /// geometry needs them) as from the general one (placements, then
        /// `f` through them), in full and first-contact queries, and the
        /// very `f`: random radii, unit (`r²/|r|²`) and non-unit
        /// quaternions, short and long rationals (up to about 100 digits),
        /// bodies apart or overlapping at random, and constructions that
        /// touch (externally, tangent along A's first axis, then turned and
        /// moved as a whole; ellipsoids and spheres), overlap slightly, or
        /// coincide.
        #[test]
        fn static_pairs_take_the_lean_route_to_the_same_outcome(
            radii in proptest::collection::vec((1i64..40, 1i64..9), 6),
            r in proptest::collection::vec(-6i64..7, 4),
            unit in proptest::bool::ANY,
            centres in proptest::collection::vec((-60i64..60, 1i64..12), 6),
            long in 0u32..60,
            kind in 0usize..5,
            span in (-5i64..5, 1i64..7),
        ) {
            // A long rational: n/d times 3^long / 7^(long/2).
            let scale = Rat::new(Int::from(3).pow(long), Int::from(7).pow(long / 2)).expect("nonzero");
            let rat = |(n, d): (i64, i64)| &Rat::from_frac(n, d) * &scale;
            let mut r: Quat = std::array::from_fn(|i| Rat::from(r[i]));
            if r.iter().all(Rat::is_zero) {
                r[0] = Rat::one();
            }
            // r²/|r|² is a unit quaternion.
            let q: Quat = if unit {
                let n = norm2(&r);
                let [w, x, y, z] = &r;
                let two_w = &Rat::from(2) * w;
                let square = [&(w * w) - &(&(&(x * x) + &(y * y)) + &(z * z)), &two_w * x, &two_w * y, &two_w * z];
                square.map(|c| &c / &n)
            } else {
                r.each_ref().map(|c| &(c * &scale) / &Rat::from(7))
            };
            // Kind 4: spheres that touch (Theorem 3.10's case (2b)).
            let axis = |i: usize| if kind == 4 { 0 } else { i };
            let ra: Vec3 = std::array::from_fn(|i| rat(radii[axis(i)]));
            let rb: Vec3 = std::array::from_fn(|i| rat(radii[3 + axis(i)]));
            let ca: Vec3 = std::array::from_fn(|i| rat(centres[i]));
            let cb: Vec3 = match kind {
                // Tangent at A's first axis (kind 1), or overlapping by a
                // little (kind 2), turned by q and moved to ca.
                1 | 2 | 4 => {
                    let gap = if kind != 2 { Rat::zero() } else { Rat::from_frac(1, 1000) };
                    let offset = [&(&ra[0] + &rb[0]) - &gap, Rat::zero(), Rat::zero()];
                    let turned = rotate(&q, &offset);
                    std::array::from_fn(|i| &ca[i] + &turned[i])
                }
                // The same place (the same body when the radii agree).
                3 => ca.clone(),
                _ => std::array::from_fn(|i| rat(centres[3 + i])),
            };
            let body = |radii: Vec3, center: Vec3| Body {
                radii,
                motion: Motion::Static { center, orientation: q.clone() },
            };
            let t0 = Rat::from(span.0);
            let scene = Scene { span: [t0.clone(), &t0 + &Rat::from(span.1)], a: body(ra, ca), b: body(rb, cb) };
            proptest::prop_assert!(scene.validate().is_ok());
            let (pa, pb) = (
                placed_quadric(&scene.a, &scene.span).expect("static"),
                placed_quadric(&scene.b, &scene.span).expect("static"),
            );
            let f = CharPoly::of_static(&scene.a, &scene.b);
            proptest::prop_assert_eq!(&f, &Some(CharPoly::from_placed(&pa, &pb)));
            // The degree of sr0 read without forming it is its degree.
            let sr0_degree = Coefficients::new(f.expect("static")).degree(Quantity::Sr0);
            for first_contact_only in [false, true] {
                let opts = Options { first_contact_only, ..Options::default() };
                let lean = ccd_algorithm::run(Exact::new(&scene, opts.digits).expect("static"), &opts);
                let general = ccd_algorithm::run(Exact::with(&scene, opts.digits, None).expect("static"), &opts);
                proptest::prop_assert_eq!(format!("{lean:?}"), format!("{general:?}"));
                let stats = lean.expect("a static pair's query").stats;
                if stats.branch.is_some() {
                    proptest::prop_assert_eq!(stats.deg_sr0, sr0_degree);
                }
            }
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]
        /// A sample's signs through the `f64` interval filter are the exact
        /// signs, on long coefficients (up to about 1100 bits, beyond
        /// `f64`'s range once multiplied) and on coefficients where the
        /// closed forms vanish or nearly cancel: `f = (λ − r)²·(λ² + aλ + b)`
        /// scaled, and the same with one coefficient nudged by 1.
        #[test]
        fn sample_signs_are_exact(
            r in -50i64..50, a in -50i64..50, b in -50i64..50,
            scale in 0u32..1100, nudge in 0usize..6, raw in proptest::collection::vec(-1000i64..1000, 5),
        ) {
            let s = Int::one().shl(scale as u64);
            let (r, a, b) = (Int::from(r), Int::from(a), Int::from(b));
            // (λ² − 2rλ + r²)(λ² + aλ + b), high → low.
            let two_r = &r * &Int::from(2);
            let r2 = &r * &r;
            let structured = [
                Int::one(),
                &a - &two_r,
                &(&b - &(&two_r * &a)) + &r2,
                &(&r2 * &a) - &(&two_r * &b),
                &r2 * &b,
            ];
            let random: [Int; 5] = std::array::from_fn(|k| Int::from(raw[k]));
            for base in [structured, random] {
                let mut v: [Int; 5] = base.each_ref().map(|c| c * &s);
                if nudge < 5 {
                    v[nudge] = &v[nudge] + &Int::one();
                }
                let exact = closed_forms(&v);
                let mut sample = Sample::new(Rat::zero(), v.clone());
                for q in QUANTITIES {
                    let want = exact.get(q).map_or(0, Int::signum);
                    proptest::prop_assert_eq!(sample.sign(q, || false, || unreachable!("given")), want, "{:?} of {:?}", q, v);
                }
            }
        }
    }
}

/// Algorithm 1 with the touch test's other certificates (the states on
/// both sides, the interior witness) against the signs alone, on every
/// stability scene: the same answers.
#[cfg(test)]
mod certificates {
    use super::{Exact, ExactRoot};
    use ccd_algorithm::{
        At, Candidates, CcdError, Decided, Item, Options, Oracle, Signs, Vanishing,
    };
    use ccd_arith::Rat;
    use ccd_scene::Scene;
    use ccd_subres::Quantity;
    use ccd_timeline::{Geometry, Instant, Outcome, Path, State, Stats};

    /// The exact oracle whose roots are decided by their signs alone.
    struct SignsOnly<'s>(Exact<'s>);

    impl Oracle for SignsOnly<'_> {
        type Root = ExactRoot;
        const PATH: Path = Path::Exact;
        const SAMPLE_AT_ENDS: bool = true;
        const LEVELS: usize = 2;

        fn domain(&self) -> &[Rat; 2] {
            self.0.domain()
        }
        fn time(&self, x: &Rat) -> Rat {
            self.0.time(x)
        }
        fn signs<'a>(&'a self, at: At<'a, ExactRoot>, level: usize) -> Box<dyn Signs + 'a> {
            self.0.signs(at, level)
        }
        fn guess(&self, x: &Rat) -> State {
            self.0.guess(x)
        }
        fn prepare(&mut self) -> Result<(), CcdError> {
            self.0.prepare()
        }
        fn vanishes(&mut self, q: Quantity) -> Vanishing {
            Oracle::vanishes(&mut self.0, q)
        }
        fn candidates(&self, q: Quantity, attempt: usize) -> Option<Candidates<'_, ExactRoot>> {
            self.0.candidates(q, attempt)
        }
        fn ends(&self, r: &ExactRoot) -> (Rat, Rat) {
            Oracle::ends(&self.0, r)
        }
        fn refine(&self, r: &mut ExactRoot, q: Quantity) -> Instant {
            self.0.refine(r, q)
        }
        fn geometry(&self, r: &mut ExactRoot, zeros: &[Quantity], instant: &Instant) -> Geometry {
            self.0.geometry(r, zeros, instant)
        }
        fn geometry_at(&self, x: &Rat, zeros: &[Quantity]) -> Geometry {
            self.0.geometry_at(x, zeros)
        }
        fn touch_between_contacts(&self, x: &Rat, d: Decided) -> Result<Decided, CcdError> {
            self.0.touch_between_contacts(x, d)
        }
        fn settle(&self, items: Vec<Item>) -> Vec<Item> {
            self.0.settle(items)
        }
        fn stats(&self, stats: &mut Stats) {
            self.0.stats(stats)
        }
    }

    /// Two enclosures of the same instant meet.
    fn meet(a: &Instant, b: &Instant) -> bool {
        a.lo <= b.hi && b.lo <= a.hi
    }

    fn same_answer(x: &Outcome, y: &Outcome) -> bool {
        x.collision_free == y.collision_free
            && x.contacts.len() == y.contacts.len()
            && x.contacts.iter().zip(&y.contacts).all(|(a, b)| meet(a, b))
            && x.timeline.len() == y.timeline.len()
            && x.timeline.iter().zip(&y.timeline).all(|(a, b)| {
                a.state == b.state && meet(&a.start, &b.start) && meet(&a.end, &b.end)
            })
    }

    #[test]
    fn the_certificates_change_no_answer() {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../../tests/stability");
        let mut scenes: Vec<_> = std::fs::read_dir(dir)
            .expect("the stability scenes")
            .map(|e| e.expect("an entry").path())
            .filter(|p| p.extension().is_some_and(|x| x == "toml"))
            .collect();
        scenes.sort();
        assert!(scenes.len() >= 100, "{}", scenes.len());
        let opts = Options {
            first_contact_only: false,
            ..Options::default()
        };
        for path in &scenes {
            let text = std::fs::read_to_string(path).expect("a scene");
            let scene = Scene::from_toml(&text).expect("a pair scene");
            let with = ccd_algorithm::run(Exact::new(&scene, opts.digits).expect("valid"), &opts);
            let without = ccd_algorithm::run(
                SignsOnly(Exact::new(&scene, opts.digits).expect("valid")),
                &opts,
            );
            match (with, without) {
                (Ok(x), Ok(y)) => assert!(same_answer(&x, &y), "{}", path.display()),
                (x, y) => assert_eq!(x.is_ok(), y.is_ok(), "{}", path.display()),
            }
        }
    }
}
