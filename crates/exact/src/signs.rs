//! Signs of `sr22, sr20, sr11, sr10` at the roots of `sr0`, from the
//! coefficients of `f(λ; t)` instead of from those four polynomials.
//!
//! Algorithm 1 isolates the roots of `sr0` (or `sr11`), so that polynomial
//! is formed; the other closed forms are read only as signs at a few
//! algebraic instants. [`RealRoot::sign_with`] needs of a quantity `q` near
//! a root only enclosures of `q` and `q″` over an interval, `q(m)` and
//! `q′(m)` at a dyadic point, and `q` exactly when `q(α) = 0` must be
//! decided. Every closed form `Q` of Section 4 is a polynomial in the five
//! coefficients `f_k(t)`, homogeneous of degree `w` (2 for `sr22, sr20`, 4
//! for `sr11, sr10`), so all of those come from the `f_k` by running the
//! same generic [`closed_forms`] over other rings:
//!
//! * `q(X)`: over `f64` intervals of `f_k(X)`;
//! * `q″(X)`: over second-order jets [`Jet2`] of `(f_k, f_k′, f_k″)(X)`;
//! * `q(m), q′(m)` exactly: over dual numbers of the exact homogeneous
//!   values `2^(jn)·(f_k(m), f_k′(m))` at `m = a/2^j` (so the result is
//!   `2^(jnw)·(q(m), q′(m))`), for degree-`n` polynomials `f_k` with
//!   coefficients far shorter than those of the degree-`4n`/`6n` forms;
//! * `q mod p` for one word prime `p`: over [`Residues`] of the `f_k`; it
//!   usually proves `gcd(sr0, q) = 1`, hence `q(α) ≠ 0`, when `q(α)` is
//!   too small for the enclosures to tell from zero;
//! * `q` itself only if a zero has to be decided and the image cannot
//!   prove it away (rare; formed once).
//!
//! `sr0` alone is formed as a polynomial ([`closed_form`], 13 of the 17
//! products of the closed forms).

use ccd_arith::{BigInterval, Dual, DwBall, Dyadic, Int, Interval, Jet2, Rat, RingOps};
use ccd_motion::CharPoly;
use ccd_poly::{Residues, SmallPoly, ZPoly};
use ccd_solver::{ball_horner, ball_value, ball_view, BallJet, ExactJet, ScaledPoly, SignModel};
use ccd_subres::{closed_form, homogeneous_degree, isobaric_weight, Quantity};
use std::cell::RefCell;
use std::rc::Rc;
use std::sync::OnceLock;

/// Below `degree·bits` of this, a closed form over [`SmallPoly`] (`i128`)
/// is tried first: its products of up to `deg f + 1` terms and the forms'
/// constants (up to 27³) add well under the 26 bits left to 126.
const SMALL_BITS: u64 = 100;

/// Bits kept in front of the binary point of the largest scaled
/// coefficient: products of four values stay far inside `f64`'s range.
const VIEW_BITS: i64 = 100;

/// The coefficients of `f(λ; t)` (high → low in λ) and what the sign models
/// need of them, shared by the models of all quantities.
pub(crate) struct Coefficients {
    f: CharPoly,
    /// `f_k · 2^(tilt·(4 − k) − shift)` in `f64` (`k` high → low).
    views: [ScaledPoly; 5],
    shift: i64,
    /// The rescaling `λ ↦ 2^tilt·λ` of the views ([`balancing`]) before
    /// the common shift: with one shift for all, the shortest `f_k` would
    /// sit its spread from the longest below `2^100`, and products of four
    /// below `f64`'s range (`bench-perturbed-rigid-deg2-d0030`: 1,825 to
    /// 3,476 bits). A power of two changes no rounding elsewhere.
    tilt: i64,
    /// The closed forms as polynomials, each formed on first need
    /// (indexed by [`slot`]).
    polys: [OnceLock<ZPoly>; 5],
    /// Each closed form's constant term and nominal top coefficient
    /// ([`Coefficients::extreme`], indexed by [`End`]), each formed on
    /// first need.
    extremes: [[OnceLock<Int>; 2]; 5],
    /// Whether each closed form vanishes identically
    /// ([`Coefficients::vanishes_identically`]), decided once.
    zero: [OnceLock<bool>; 5],
    /// A repeated factor of `f` in `λ` common to every `t`
    /// ([`CharPoly::fixed_repeated_factor`]), looked for once.
    fixed: OnceLock<Option<ZPoly>>,
    /// The views' values in double-word balls (each low → high in `u`),
    /// formed on first need.
    balls: OnceLock<[Vec<DwBall>; 5]>,
    /// The `f_k` modulo the word prime of [`Residues`], formed on first
    /// need (every quantity's image is a closed form of these).
    images: OnceLock<[Residues; 5]>,
    /// The last point's jets: the quantities at one root are asked for at
    /// the same point.
    last: RefCell<Option<(Rat, [Dual<Int>; 5])>>,
    /// The last point's jets in balls, likewise.
    last_ball: RefCell<Option<(Rat, [Dual<DwBall>; 5])>>,
    /// The last interval's enclosures of `f_k` and, once
    /// [`SignModel::enclose_second`] needed them there, of `(f_k′, f_k″)`,
    /// likewise.
    last_box: RefCell<Option<BoxValues>>,
}

/// Enclosures of the `f_k` over an interval, and of their first and second
/// derivatives when formed.
struct BoxValues {
    at: Interval,
    values: [Interval; 5],
    derivatives: Option<[(Interval, Interval); 5]>,
}

impl Coefficients {
    pub(crate) fn new(f: CharPoly) -> Coefficients {
        let sizes = f
            .coeffs
            .each_ref()
            .map(|c| (!c.is_zero()).then(|| c.max_bits() as i64));
        let (tilt, _) = balancing(|k| sizes[k].map(|b| b as f64));
        let bits = (0..5)
            .filter_map(|k| sizes[k].map(|b| b + tilt * (4 - k as i64)))
            .max()
            .unwrap_or(0);
        let shift = (bits - VIEW_BITS).max(0);
        Coefficients {
            views: std::array::from_fn(|k| {
                ScaledPoly::with_shift(&f.coeffs[k], view_shift(shift, tilt, k))
            }),
            f,
            shift,
            tilt,
            polys: Default::default(),
            extremes: Default::default(),
            zero: Default::default(),
            fixed: OnceLock::new(),
            balls: OnceLock::new(),
            images: OnceLock::new(),
            last: RefCell::new(None),
            last_ball: RefCell::new(None),
            last_box: RefCell::new(None),
        }
    }

    /// Enclosures of the views `f_k·2^(tilt·(4 − k) − shift)` at `u`
    /// (interval Horner at `u`'s enclosure): `f`'s coefficients there up to
    /// one positive factor and a positive rescaling of `λ`, which keep
    /// every sign Theorem 3.10 reads.
    pub(crate) fn views_at(&self, u: &Rat) -> [Interval; 5] {
        ScaledPoly::enclose_each(self.views.each_ref(), Interval::from_rat(u))
    }

    /// The closed form `q` (not [`Quantity::Var`]) as a polynomial, formed
    /// once, with only the products it needs: in `i128` ([`SmallPoly`],
    /// which detects any overflow) when short inputs make its numbers
    /// small (`|q| < 2^(degree·bits + a few)`, [`homogeneous_degree`]), else
    /// over `Z[t]`.
    pub(crate) fn polynomial(&self, q: Quantity) -> &ZPoly {
        self.polys[slot(q)].get_or_init(|| {
            if self.short(q) {
                let small = self.f.coeffs.each_ref().map(SmallPoly::lowered);
                if let Some(p) = closed_form(&small, q).and_then(|p| p.to_zpoly()) {
                    return p;
                }
            }
            closed_form(&self.f.coeffs, q).expect("a closed form, not Var")
        })
    }

    /// Whether `q`'s numbers are short enough to form it in `i128` first
    /// (`|q| < 2^(degree·bits + a few)`, [`homogeneous_degree`]).
    pub(crate) fn short(&self, q: Quantity) -> bool {
        let bits = self.f.coeffs.iter().map(ZPoly::max_bits).max().unwrap_or(0);
        homogeneous_degree(q) * bits <= SMALL_BITS
    }

    /// Whether the closed form `q` is the zero polynomial, decided exactly
    /// and once. For `sr0`, first by a repeated factor of `f` in `λ` common
    /// to every `t` ([`CharPoly::fixed_repeated_factor`]: usually one gcd
    /// of quartics modulo a prime and a few evaluations). Where it finds
    /// one, that costs less than forming `sr0`, even in `i128`, and the
    /// factor is also `sr11`'s hint ([`Coefficients::triple_root_instants`]);
    /// where not, it is spent besides. Otherwise, and at once when `f` is
    /// constant in `t` (then `q` is one closed form of integers), by
    /// forming `q`.
    pub(crate) fn vanishes_identically(&self, q: Quantity) -> bool {
        *self.zero[slot(q)].get_or_init(|| {
            let fixed = || {
                self.fixed
                    .get_or_init(|| self.f.fixed_repeated_factor())
                    .is_some()
            };
            (q == Quantity::Sr0 && self.f.degree() != 0 && fixed()) || self.polynomial(q).is_zero()
        })
    }

    /// Where `f(λ; t)` has a triple root, when `sr0 ≡ 0` was proven by a
    /// linear fixed factor `h = h₀ + h₁λ` (`h² | f`, so `f = h²·g`): the
    /// instants where `g(c) = 0` too, `c = −h₀/h₁`, i.e. the zeros of
    /// `h₁²·f″(c)/2 ∝ Σ_m m(m − 1)·f_m·(−h₀)^(m−2)·h₁^(4−m)` (`f_m` the
    /// coefficient of `λ^m`). There `gcd(f, ∂f/∂λ)` has degree 2, so
    /// `sr11` vanishes, in the families seen to even multiplicity: the
    /// hint [`ccd_solver::isolate_with`] takes for `sr11`'s squarefree part
    /// (proven or dropped there). `None` without such an `h` (also when
    /// the test did not run).
    pub(crate) fn triple_root_instants(&self) -> Option<ZPoly> {
        let h = self.fixed.get()?.as_ref()?;
        let [h0, h1] = h.coeffs() else {
            return None;
        };
        let minus_h0 = -h0;
        let term = |m: u32| {
            let scale = Int::from(i64::from(m * (m - 1))) * minus_h0.pow(m - 2) * h1.pow(4 - m);
            self.f.coeffs[4 - m as usize].mul_int(&scale)
        };
        let g = term(2).plus(&term(3)).plus(&term(4));
        (g.degree()? >= 1).then_some(g)
    }

    /// Whether [`Coefficients::vanishes_identically`] has found `q ≡ 0`
    /// (without deciding it when it has not run).
    pub(crate) fn proven_zero(&self, q: Quantity) -> bool {
        self.zero[slot(q)].get() == Some(&true)
    }

    /// The `f_k`'s coefficients of `t^0` ([`End::First`]) or `t^n`
    /// ([`End::Last`]), `k` high → low.
    fn end_coefficients(&self, end: End) -> [Int; 5] {
        let i = match end {
            End::First => 0,
            End::Last => self.f.degree(),
        };
        std::array::from_fn(|k| {
            self.f.coeffs[k]
                .coeffs()
                .get(i)
                .cloned()
                .unwrap_or_else(Int::zero)
        })
    }

    /// The constant term `q(0)` ([`End::First`]) or the nominal top
    /// coefficient (of `t^(w·n)`, [`End::Last`]) of the closed form `q` of
    /// weight `w`, computed once: `q` is homogeneous of degree `w` in the
    /// `f_k`, so these are `q` of the `f_k`'s coefficients of `t^0` and of
    /// `t^n`.
    ///
    /// Read off the polynomial `q` when that is formed
    /// ([`Coefficients::polynomial`]): its coefficients of `t^0` and
    /// `t^(w·n)` are these.
    fn extreme(&self, q: Quantity, end: End) -> &Int {
        self.extremes[slot(q)][end as usize].get_or_init(|| match self.polys[slot(q)].get() {
            Some(p) => p.coeff(match end {
                End::First => 0,
                End::Last => homogeneous_degree(q) as usize * self.f.degree(),
            }),
            None => closed_form(&self.end_coefficients(end), q).expect("a closed form, not Var"),
        })
    }

    /// A lower bound on the bits of [`Coefficients::extreme`] when it is
    /// nonzero: its own bits when at hand, else, for long values (as
    /// [`interval_sign`]'s), from an enclosure of the closed form in
    /// [`INTERVAL_SIGN_BITS`]`[0]`-bit intervals that excludes zero
    /// (`|x| ≥ |m|·2^e ≥ 2^(bits m − 1 + e)` at its end `m·2^e` nearer to
    /// zero). `None` when neither tells: the extreme is then formed. On
    /// `bench-perturbed-affine-deg2-d0100` the top coefficient of `sr0`
    /// has 28,000 bits (0.85M instructions), its enclosure a tenth of that.
    fn extreme_bits_at_least(&self, q: Quantity, end: End) -> Option<u64> {
        if self.extreme_at_hand(q, end) {
            let x = self.extreme(q, end);
            return (!x.is_zero()).then(|| x.bits());
        }
        // Short `f` (the usual case) without copying its end coefficients.
        if self
            .f
            .coeffs
            .iter()
            .all(|c| c.max_bits() < INTERVAL_SIGN_MIN_BITS)
        {
            return None;
        }
        let values = self.end_coefficients(end);
        if values.iter().map(Int::bits).max()? < INTERVAL_SIGN_MIN_BITS {
            return None;
        }
        let x = interval_closed_form(&values, q, INTERVAL_SIGN_BITS[0])?;
        let nearer = match x.sign()? {
            1 => &x.lo,
            -1 => &x.hi,
            _ => return None,
        };
        Some((nearer.m.bits() as i64 + nearer.e).max(1) as u64)
    }

    /// Whether [`Coefficients::extreme`] costs no closed form: formed, or
    /// read off the formed polynomial.
    fn extreme_at_hand(&self, q: Quantity, end: End) -> bool {
        self.extremes[slot(q)][end as usize].get().is_some() || self.polys[slot(q)].get().is_some()
    }

    /// Whether `m ≠ 0` divides [`Coefficients::extreme`] (zero included),
    /// without forming it when it is not yet, `|m|` is short and `f` long
    /// ([`Coefficients::long`]): `q` is a
    /// polynomial with integer coefficients in the `f_k`'s, so its value at
    /// their residues modulo `m` is congruent to it. For `x` of
    /// [`SignModel::admits_root_at`] the extremes have up to `6·w·n` times
    /// the bits of `f` (`bench-perturbed-affine-deg2-d0100`: 28,000, at
    /// 0.85M instructions each), the residues a few words.
    fn extreme_divisible_by(&self, q: Quantity, end: End, m: &Int) -> bool {
        if !self.extreme_at_hand(q, end) && m.bits() <= SHORT_MODULUS_BITS && self.long() {
            let m = m.abs();
            let residue = |x: Int| x.div_rem_trunc(&m).1;
            let c = self.end_coefficients(end).map(residue);
            return residue(closed_form(&c, q).expect("a closed form, not Var")).is_zero();
        }
        let x = self.extreme(q, end);
        x.is_zero() || x.is_divisible_by(m)
    }

    /// Whether some `f_k` has a coefficient of more than
    /// [`LONG_COEFFICIENT_BITS`] bits: below, the extremes cost less than
    /// their residues and the extreme itself, which a later step may need.
    fn long(&self) -> bool {
        self.f
            .coeffs
            .iter()
            .any(|c| c.max_bits() > LONG_COEFFICIENT_BITS)
    }

    /// Whether [`Coefficients::extreme`] is zero: not when its residue
    /// modulo the prime [`ZERO_TEST_PRIME`] is not, else (a zero residue)
    /// exactly.
    fn extreme_is_zero(&self, q: Quantity, end: End) -> bool {
        self.extreme_divisible_by(q, end, &Int::from(ZERO_TEST_PRIME))
            && self.extreme(q, end).is_zero()
    }

    /// `deg q` (`None` when `q ≡ 0`), without forming `q` when its nominal
    /// top coefficient (of `t^(w·n)`, `w` its degree in the `f_k`:
    /// `t^(6n)` for `sr0`, `t^(4n)` for `sr11`) is nonzero.
    pub(crate) fn degree(&self, q: Quantity) -> Option<usize> {
        if self.extreme_is_zero(q, End::Last) {
            self.polynomial(q).degree()
        } else {
            Some(homogeneous_degree(q) as usize * self.f.degree())
        }
    }

    /// Whether `q` has been formed as a polynomial.
    pub(crate) fn formed(&self, q: Quantity) -> bool {
        self.polys[slot(q)].get().is_some()
    }

    /// The shift of view `k` (high → low) ([`view_shift`]).
    fn view_shift(&self, k: usize) -> i64 {
        view_shift(self.shift, self.tilt, k)
    }

    /// `−log2 σ` for `q`: the closed form of the views is `σ·q` with `σ =
    /// 2^(tilt·i − shift·w)`, `q` being homogeneous of degree `w` and
    /// isobaric of weight `i` ([`isobaric_weight`]) in the `f_k`.
    fn sigma_exp(&self, q: Quantity) -> i64 {
        self.shift * weight(q) - self.tilt * isobaric_weight(q) as i64
    }

    /// `f(λ; u)`.
    pub(crate) fn char_poly(&self) -> &CharPoly {
        &self.f
    }
}

/// [`balancing`]'s size of a double-word ball: `log2` of its leading
/// word, `None` for a zero one.
fn ball_log2(b: &DwBall) -> Option<f64> {
    (b.hi != 0.0).then(|| b.hi.abs().log2())
}

/// The balancing of the coefficients `a_k` of `λ^k` (`log2 |a_k|` by
/// `log2(4 − k)`, `None` for zero) before a closed form in `f64`-ranged
/// balls: `λ → 2^e·λ` balances the highest and lowest nonzero ones
/// (`a_k1·2^(k1·e)` against `a_k0·2^(k0·e)`: sizes far apart would
/// underflow the products), then `2^g` brings the largest near 1. The
/// forms are homogeneous of degree `w` and isobaric of weight `i`, so
/// `2^(−e·i − g·w)` undoes it exactly.
fn balancing(log2: impl Fn(usize) -> Option<f64>) -> (i64, i64) {
    // (power of λ, log2 |a_k|), highest power first.
    let sizes = (0..5).filter_map(|i| log2(i).map(|l| (4 - i as i64, l)));
    let e = match (sizes.clone().next(), sizes.clone().next_back()) {
        (Some((k1, l1)), Some((k0, l0))) if k1 > k0 => {
            ((l0 - l1) / (k1 - k0) as f64).round() as i64
        }
        _ => 0,
    };
    let top = sizes
        .map(|(k, l)| l + (e * k) as f64)
        .fold(f64::NEG_INFINITY, f64::max);
    let g = if top.is_finite() {
        -top.round() as i64
    } else {
        0
    };
    (e, g)
}

/// The sign model of `q` (not [`Quantity::Var`]) over shared coefficients.
pub(crate) fn model(f: &Rc<Coefficients>, q: Quantity) -> ClosedForm {
    ClosedForm { f: f.clone(), q }
}

/// Which extreme coefficient of a closed form ([`Coefficients::extreme`]).
#[derive(Clone, Copy)]
enum End {
    /// The constant term.
    First = 0,
    /// The nominal top coefficient.
    Last = 1,
}

/// Moduli of at most this many bits divide an extreme through residues
/// ([`Coefficients::extreme_divisible_by`]).
const SHORT_MODULUS_BITS: u64 = 128;

/// The Mersenne prime `2^61 − 1`, whose residue tells a nonzero extreme
/// ([`Coefficients::extreme_is_zero`]).
const ZERO_TEST_PRIME: i64 = (1 << 61) - 1;

/// Coefficients of `f` longer than this make its extremes worth avoiding
/// ([`Coefficients::long`]).
const LONG_COEFFICIENT_BITS: u64 = 512;

/// The cache slot of a closed form.
fn slot(q: Quantity) -> usize {
    match q {
        Quantity::Sr22 => 0,
        Quantity::Sr20 => 1,
        Quantity::Sr11 => 2,
        Quantity::Sr10 => 3,
        Quantity::Sr0 | Quantity::Var => 4,
    }
}

/// The shift of view `k` (high → low, the coefficient of `λ^(4 − k)`):
/// the view is `f_k·2^(−view_shift)`, `λ ↦ 2^tilt·λ` then one shift.
fn view_shift(shift: i64, tilt: i64, k: usize) -> i64 {
    shift - tilt * (4 - k as i64)
}

/// Homogeneous degree of each closed form in the coefficients of `f`.
fn weight(q: Quantity) -> i64 {
    match q {
        Quantity::Sr22 | Quantity::Sr20 => 2,
        Quantity::Sr11 | Quantity::Sr10 => 4,
        Quantity::Sr0 => 6,
        Quantity::Var => 0,
    }
}

/// The closed form `q` of `f`'s coefficients as a [`SignModel`], with
/// `σ = 2^(tilt·i − shift·w)` (`Coefficients::sigma_exp`).
#[derive(Clone)]
pub struct ClosedForm {
    f: Rc<Coefficients>,
    q: Quantity,
}

/// The precisions up to which [`SignModel::big_jet_at`] takes the
/// closed form in balanced double-word balls (`ClosedForm::balanced_exact`)
/// before intervals: the sign rounds' (128 bits), not the Newton jumps'.
const BALANCED_BITS: u32 = 128;

/// Precisions (bits) of [`interval_sign`]'s tries.
const INTERVAL_SIGN_BITS: [u32; 2] = [256, 1024];

/// [`interval_sign`] runs only for values of at least this many bits:
/// shorter ones cost less exactly (values of 750 bits: about 25K
/// instructions for the exact closed form, 100K in 256-bit intervals,
/// which carry two ends and round every operation; on the stability
/// families a bound of 1536 loses nothing, no bound made 27 scenes dearer,
/// up to +54 %).
const INTERVAL_SIGN_MIN_BITS: u64 = 1536;

/// The sign of the closed form `q` of the exact `values` (of at least
/// [`INTERVAL_SIGN_MIN_BITS`]), when an enclosure in multi-precision
/// intervals ([`BigInterval`], rounded outward) excludes zero: at 256,
/// then 1024 bits, each only while it is
/// at most a quarter of the bits the exact products reach (`q` is
/// homogeneous of degree `w` in the values: about `w` times their
/// length), where the exact closed form costs little more. Values at a
/// point next to a root cancel to far below their size, but on the long
/// numbers of nearly degenerate scenes (`bench-perturbed-*`) rarely to
/// below 256 bits of it. `None` when no try decides.
fn interval_sign(values: &[Int; 5], q: Quantity) -> Option<i32> {
    let bits = values.iter().map(Int::bits).max()?;
    if bits < INTERVAL_SIGN_MIN_BITS {
        return None;
    }
    let exact_bits = bits * homogeneous_degree(q);
    INTERVAL_SIGN_BITS
        .into_iter()
        .take_while(|&p| 4 * u64::from(p) <= exact_bits)
        .find_map(|p| {
            interval_closed_form(values, q, p)?
                .sign()
                .filter(|s| *s != 0)
        })
}

/// The closed form `q` of the exact `values` in `prec`-bit intervals.
fn interval_closed_form(values: &[Int; 5], q: Quantity, prec: u32) -> Option<BigInterval> {
    let enclose = |v: &Int| {
        let d = Dyadic::from_int(v);
        BigInterval::new(d.clone(), d, prec)
    };
    closed_form(&values.each_ref().map(enclose), q)
}

impl ClosedForm {
    /// `q` of five ring values.
    fn of<R: RingOps>(&self, values: &[R; 5]) -> R {
        closed_form(values, self.q).expect("a closed form, not Var")
    }

    /// `(F_k, G_k) = (b^n·f_k(x), b^n·f_k′(x))` for `x = a/b` with the
    /// common `n` (each `f_k` evaluated homogeneously, then brought to
    /// degree `n`), so that `Q(F + εG) = b^(nw)·(q(x) + ε·q′(x))`; handed
    /// to `read`, and cached for the last `x` (shared by the closed forms
    /// of one `f`; `read` must not ask for jets itself).
    fn with_jets<T>(&self, x: &Rat, read: impl FnOnce(&[Dual<Int>; 5]) -> T) -> T {
        if let Some((at, jets)) = &*self.f.last.borrow() {
            if at == x {
                return read(jets);
            }
        }
        let jets = self.compute_jets(x);
        let out = read(&jets);
        *self.f.last.borrow_mut() = Some((x.clone(), jets));
        out
    }

    fn compute_jets(&self, x: &Rat) -> [Dual<Int>; 5] {
        let n = self.f.f.degree();
        // v·b^e: a shift at dyadic points.
        let times_b_pow = |v: Int, e: usize| match x.dyadic_exponent() {
            Some(j) => v.shl(j * e as u64),
            None => &v * &x.denom().pow(e as u32),
        };
        std::array::from_fn(|k| {
            let p = &self.f.f.coeffs[k];
            let nk = p.degree().unwrap_or(0);
            let (v, d) = p.eval_homogeneous_with_derivative(x);
            // v = b^nk·f(x), d = b^(nk−1)·f′(x) (d = 0 for constants).
            Dual {
                v: times_b_pow(v, n - nk),
                d: times_b_pow(d, n + 1 - nk.max(1)),
            }
        })
    }
}

impl ClosedForm {
    /// `(f_k(m), f_k′(m))·2^(−shift)` in balls at a dyadic `m` (Horner on
    /// the balls of the coefficients), cached for the last `m`; `None` when
    /// `m` itself is no exact ball.
    fn ball_jets(&self, m: &Rat) -> Option<[Dual<DwBall>; 5]> {
        if let Some((at, jets)) = &*self.f.last_ball.borrow() {
            if at == m {
                return Some(*jets);
            }
        }
        let x = DwBall::exactly(m)?;
        let balls = self.coefficient_balls();
        let jets: [Dual<DwBall>; 5] = std::array::from_fn(|k| ball_horner(&balls[k], &x));
        *self.f.last_ball.borrow_mut() = Some((m.clone(), jets));
        Some(jets)
    }

    /// The views' coefficients in double-word balls (formed on first need).
    fn coefficient_balls(&self) -> &[Vec<DwBall>; 5] {
        self.f.balls.get_or_init(|| {
            std::array::from_fn(|k| ball_view(&self.f.f.coeffs[k], self.f.view_shift(k)))
        })
    }

    /// Enclosures of `f_k` over `x` (scaled), cached for the last `x`
    /// (with the derivatives' when formed there).
    fn box_values(&self, x: Interval) -> [Interval; 5] {
        if let Some(b) = &*self.f.last_box.borrow() {
            if b.at == x {
                return b.values;
            }
        }
        let values = ScaledPoly::enclose_each(self.f.views.each_ref(), x);
        *self.f.last_box.borrow_mut() = Some(BoxValues {
            at: x,
            values,
            derivatives: None,
        });
        values
    }

    /// Enclosures of `(f_k, f_k′, f_k″)` over `x` (scaled), cached for the
    /// last `x`. (`f_k′ = 0` exactly only for a constant `f_k`, whose
    /// `f_k″ = 0` too: the jets then give the nested dual numbers' bits.)
    fn box_jets(&self, x: Interval) -> [Jet2<Interval>; 5] {
        let values = self.box_values(x);
        let mut cache = self.f.last_box.borrow_mut();
        let b = cache.as_mut().expect("box_values fills the cache");
        let derivatives = *b.derivatives.get_or_insert_with(|| {
            ScaledPoly::enclose_derivatives_each(self.f.views.each_ref(), x)
        });
        std::array::from_fn(|k| {
            let (d, dd) = derivatives[k];
            Jet2 {
                v: values[k],
                d,
                dd,
            }
        })
    }

    /// The exponent `scale` of the jets at a dyadic point `a/2^j`:
    /// `σ·(q(m), q′(m)) = Q(F + εG)·2^(−scale)` ([`SignModel::exact_jet_at`]).
    fn jet_scale(&self, j: i64) -> i64 {
        j * self.f.f.degree() as i64 * weight(self.q) + self.f.sigma_exp(self.q)
    }

    /// The closed form over double-word balls of `f_k(x)` (Horner without
    /// the derivatives) at the dyadic `x`, balanced ([`ClosedForm::balanced_of`]):
    /// the ball `r` and the exponent `undo` with `Q = 2^undo·r`.
    fn balanced_value(&self, x: &Rat) -> Option<(DwBall, i64)> {
        let xb = DwBall::exactly(x)?;
        let balls = self.coefficient_balls();
        let values: [DwBall; 5] = std::array::from_fn(|k| ball_value(&balls[k], &xb));
        Some(self.balanced_of(|i| ball_log2(&values[i]), |i, k| values[i].mul_pow2(k)))
    }

    /// The closed form over double-word jets balanced into `f64`'s range
    /// ([`balancing`], by the sizes `log2` of the values), jet `i` times
    /// `2^k` given by `scaled(i, k)`: the result `r` and the exponent
    /// `undo` with `Q = 2^undo·r`.
    fn balanced_of<R: RingOps>(
        &self,
        log2: impl Fn(usize) -> Option<f64>,
        scaled: impl Fn(usize, i64) -> R,
    ) -> (R, i64) {
        let (e, g) = balancing(log2);
        let balanced: [R; 5] = std::array::from_fn(|i| scaled(i, e * (4 - i as i64) + g));
        let undo = -e * isobaric_weight(self.q) as i64 - g * weight(self.q);
        (self.of(&balanced), undo)
    }

    /// The closed form of the exact jets `(F_k, G_k)` in double-word
    /// balls, balanced into `f64`'s range ([`balancing`]) and scaled back
    /// exactly into `prec`-bit intervals: about 100 bits of `Q(F + εG)`
    /// past the closed form's cancellation, at a tenth of the cost of
    /// intervals; `None` when a ball leaves `f64`'s range all the same or
    /// keeps fewer than 60 bits.
    fn balanced_exact(&self, jets: &[Dual<Int>; 5], prec: u32) -> Option<Dual<BigInterval>> {
        let (q, undo) = self.balanced_of(
            |i| (!jets[i].v.is_zero()).then(|| jets[i].v.bits() as f64),
            |i, k| Dual {
                v: DwBall::from_int_scaled(&jets[i].v, -k),
                d: DwBall::from_int_scaled(&jets[i].d, -k),
            },
        );
        // A ball with fewer than 60 bits left (cancellation past its
        // precision) is left to the intervals.
        let tight = |b: &DwBall| b.is_known() && b.rad <= b.hi.abs() * 2f64.powi(-60);
        if !(tight(&q.v) && tight(&q.d)) {
            return None;
        }
        let big = |b: &DwBall| {
            let (lo, hi) = b.ends()?;
            let (lo, hi) = (Dyadic::from_rat_exact(&lo)?, Dyadic::from_rat_exact(&hi)?);
            Some(BigInterval::new(lo, hi, prec).mul_pow2(undo))
        };
        Some(Dual {
            v: big(&q.v)?,
            d: big(&q.d)?,
        })
    }
}

impl SignModel for ClosedForm {
    /// The closed form over `f64` intervals of `f_k(X)` (cached for the
    /// last `X`, which [`SignModel::enclose_second`] is then asked at).
    fn enclose(&self, x: Interval) -> Interval {
        self.of(&self.box_values(x))
    }

    fn enclose_second(&self, x: Interval) -> Interval {
        self.of(&self.box_jets(x)).dd
    }

    fn exact_jet_at(&self, m: &Rat) -> ExactJet {
        let j = m.dyadic_exponent().expect("a dyadic point") as i64;
        let q = self.with_jets(m, |jets| self.of(jets));
        let scale = self.jet_scale(j);
        ExactJet {
            value: q.v,
            slope: q.d,
            value_exp: scale,
            slope_exp: scale,
        }
    }

    /// The closed form over dual numbers of double-word balls of
    /// `(f_k, f_k′)(m)`: `σ·(q(m), q′(m))` within a few `2^(−100)` of the
    /// terms, for the exponents of [`SignModel::exact_jet_at`].
    fn ball_jet_at(&self, m: &Rat) -> Option<BallJet> {
        let j = m.dyadic_exponent()? as i64;
        let jets = self.ball_jets(m)?;
        let (q, undo) = self.balanced_of(
            |i| ball_log2(&jets[i].v),
            |i, k| Dual {
                v: jets[i].v.mul_pow2(k),
                d: jets[i].d.mul_pow2(k),
            },
        );
        let q = Dual {
            v: q.v.mul_pow2(undo),
            d: q.d.mul_pow2(undo),
        };
        let scale = self.jet_scale(j);
        (q.v.is_known() && q.d.is_known()).then_some(BallJet {
            value: q.v,
            slope: q.d,
            value_exp: scale,
            slope_exp: scale,
        })
    }

    /// The closed form over double-word balls of `f_k(x)` alone (Horner
    /// without the derivatives), balanced like [`SignModel::ball_jet_at`]:
    /// the sign of `q(x)` where the ball excludes zero, at about half the
    /// jet's cost.
    fn ball_sign_at(&self, x: &Rat) -> Option<i32> {
        let (q, _) = self.balanced_value(x)?;
        q.sign().filter(|s| *s != 0)
    }

    /// The value of [`SignModel::ball_sign_at`] (scaled back, as
    /// [`SignModel::ball_jet_at`]'s) and the closed form over `f64`
    /// interval dual numbers of `(f_k, f_k′)` over `x` for the slope:
    /// about half the cost of the double-word jet, whose dual numbers of
    /// balls triple the balls' products.
    fn ball_value_and_slope_over(&self, m: &Rat, x: Interval) -> Option<BallJet> {
        debug_assert!({
            let at = Interval::from_rat(m);
            x.lo <= at.lo && at.hi <= x.hi
        });
        let j = m.dyadic_exponent()? as i64;
        let (q, undo) = self.balanced_value(m)?;
        let value = q.mul_pow2(undo);
        let values = self.box_values(x);
        let slopes = ScaledPoly::enclose_slopes_each(self.f.views.each_ref(), x);
        let duals: [Dual<Interval>; 5] = std::array::from_fn(|k| Dual {
            v: values[k],
            d: slopes[k],
        });
        let slope = DwBall::from_interval(self.of(&duals).d);
        let scale = self.jet_scale(j);
        (value.is_known() && slope.is_known()).then_some(BallJet {
            value,
            slope,
            value_exp: scale,
            slope_exp: scale,
        })
    }

    /// The closed form of the exact jets `(F_k, G_k)` at `m` (cached for
    /// [`SignModel::exact_jet_at`] at the same point) for long values (at
    /// least 1,536 bits, `INTERVAL_SIGN_MIN_BITS`, below which the exact
    /// closed form costs about as much), out of `f64`'s exponent range or
    /// cancelling past the double-word balls' 106 bits: up to 128 bits
    /// (`BALANCED_BITS`) in double-word balls balanced into `f64`'s range
    /// and scaled back exactly (`ClosedForm::balanced_exact`); else, or
    /// where fewer than 60 bits survive, over dual numbers of `prec`-bit
    /// [`BigInterval`]s.
    fn big_jet_at(&self, m: &Rat, prec: u32) -> Option<BallJet<BigInterval>> {
        let j = m.dyadic_exponent()? as i64;
        let q = self.with_jets(m, |jets| {
            let bits = jets.iter().map(|d| d.v.bits().max(d.d.bits())).max()?;
            if bits < INTERVAL_SIGN_MIN_BITS || u64::from(prec) * 4 > bits * weight(self.q) as u64 {
                return None;
            }
            if prec <= BALANCED_BITS {
                if let Some(q) = self.balanced_exact(jets, prec) {
                    return Some(q);
                }
            }
            let enclose = |v: &Int| {
                let d = Dyadic::from_int(v);
                BigInterval::new(d.clone(), d, prec)
            };
            Some(self.of(&jets.each_ref().map(|d| Dual {
                v: enclose(&d.v),
                d: enclose(&d.d),
            })))
        })?;
        let scale = self.jet_scale(j);
        Some(BallJet {
            value: q.v.mul_pow2(-scale),
            slope: q.d.mul_pow2(-scale),
            value_exp: scale,
            slope_exp: scale,
        })
    }

    /// The closed form over `f64` dual numbers of `(f_k, f_k′)(x)`.
    fn approx_value_and_slope(&self, x: f64) -> (f64, f64) {
        let vd = ScaledPoly::value_and_slope_each(self.f.views.each_ref(), x);
        let q = self.of(&vd.map(|(v, d)| Dual { v, d }));
        (q.v, q.d)
    }

    /// The rational root theorem on `q`'s constant term and nominal top
    /// coefficient (a zero one, i.e. a lower degree, tells nothing).
    fn admits_root_at(&self, x: &Rat) -> bool {
        if x.numer().is_zero() {
            return self.f.extreme_is_zero(self.q, End::First);
        }
        self.f.extreme_divisible_by(self.q, End::Last, x.denom())
            && self.f.extreme_divisible_by(self.q, End::First, x.numer())
    }

    /// The nominal top coefficient when it is nonzero (then it is `q`'s
    /// leading coefficient).
    fn root_denominators(&self) -> Option<Int> {
        let last = self.f.extreme(self.q, End::Last);
        (!last.is_zero()).then(|| last.abs())
    }

    fn root_denominator_bits(&self) -> Option<u64> {
        self.f.extreme_bits_at_least(self.q, End::Last)
    }

    /// The closed form of the values `b^n·f_k(a/b)` at `x = a/b`
    /// ([`CharPoly::at_scaled`], no derivatives; `b^(nw) > 0` does not
    /// change the sign), or of the last point's jets when `x` is that point.
    ///
    /// Long values are first tried in multi-precision intervals
    /// (`interval_sign`): a sign proven there is the sign.
    fn sign_at(&self, x: &Rat) -> i32 {
        let values = match &*self.f.last.borrow() {
            Some((at, jets)) if at == x => jets.each_ref().map(|jet| jet.v.clone()),
            _ => self.f.f.at_scaled(x),
        };
        interval_sign(&values, self.q).unwrap_or_else(|| self.of(&values).signum())
    }

    fn exact(&self) -> &ZPoly {
        self.f.polynomial(self.q)
    }

    /// `q mod p` from the images of the `f_k` (the closed form over
    /// [`Residues`]: no integer larger than a word), unless `q` is already
    /// formed. Its degree is `q`'s when it is the nominal `w·n`: the image
    /// of the coefficient of `t^(w·n)` is nonzero, so that coefficient is
    /// too, and `deg q ≤ w·n`.
    fn residues(&self) -> (Residues, bool) {
        if let Some(q) = self.f.polys[slot(self.q)].get() {
            return Residues::image(q);
        }
        let images = self
            .f
            .images
            .get_or_init(|| self.f.f.coeffs.each_ref().map(Residues::of));
        let r = self.of(images);
        let kept = r.degree() == Some(homogeneous_degree(self.q) as usize * self.f.f.degree());
        (r, kept)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_subres::closed_forms;
    use ccd_subres::fixtures::{quartic, QS};
    use proptest::prelude::*;

    fn poly(c: &[i64]) -> ZPoly {
        ZPoly::from_i64s(c)
    }

    /// Coefficients 1,500 bits apart in size (a hidden rescaling of λ by
    /// `2^375`, as in `bench-perturbed-rigid-deg2-d0030`): every view keeps
    /// its value inside `f64`'s range, none underflows to 0 (with one shift
    /// for all, `c_0`'s view would sit 1,400 bits below 1).
    #[test]
    fn tilted_views_stay_in_range() {
        let coeffs: [ZPoly; 5] = std::array::from_fn(|k| {
            poly(&[k as i64 + 1, 1]).mul_int(&Int::from(2).pow(375 * (4 - k as u32)))
        });
        let f = Coefficients::new(CharPoly { coeffs });
        let half = Interval::point(0.5);
        for (k, view) in f.views.iter().enumerate() {
            let v = view.enclose(half);
            assert!(v.lo > 0.0 && v.hi.is_finite(), "view {k}: {v:?}");
            assert!(v.lo.log2().abs() < 200.0, "view {k}: {v:?}");
        }
    }

    proptest! {
        /// The bound on the extremes' bits from 256-bit intervals (long
        /// values, before the extreme is formed) holds and is tight: the
        /// exact extreme is nonzero with `bits − 1` to `bits` bits; a zero
        /// extreme gives none. Read off the formed polynomial, the bits
        /// themselves.
        #[test]
        fn extreme_bits_bound_the_exact_extreme(
            raw in proptest::collection::vec(proptest::collection::vec(-9i64..10, 3), 5),
            q in proptest::sample::select(QS.to_vec()),
        ) {
            // Past INTERVAL_SIGN_MIN_BITS.
            let scale = Int::from(7).pow(600);
            let coeffs: [ZPoly; 5] = std::array::from_fn(|k| poly(&raw[k]).mul_int(&scale));
            prop_assume!(!coeffs[0].is_zero());
            let fresh = || Coefficients::new(CharPoly { coeffs: coeffs.clone() });
            let exact = fresh();
            for end in [End::First, End::Last] {
                let x = exact.extreme(q, end).clone();
                let bound = fresh().extreme_bits_at_least(q, end);
                if x.is_zero() {
                    prop_assert_eq!(bound, None);
                } else {
                    let b = bound.expect("short closed form of long values: the intervals decide");
                    prop_assert!(b <= x.bits() && b + 1 >= x.bits(), "{} against {}", b, x.bits());
                }
                let read = fresh();
                read.polynomial(q);
                prop_assert_eq!(read.extreme_bits_at_least(q, end), (!x.is_zero()).then(|| x.bits()));
            }
        }

        /// Divisibility of the extremes through residues (long `f`, short
        /// moduli, before the extreme is formed) is the formed extreme's,
        /// and so is the zero test; moduli include divisors of the
        /// extreme, and `f` has a shared factor `2^e·3` so that some do.
        /// Extremes read off the formed polynomial are the closed form's.
        #[test]
        fn extremes_by_residues_are_the_exact_ones(
            raw in proptest::collection::vec(proptest::collection::vec(-9i64..10, 3), 5),
            e in 0u32..4,
            m in 1i64..1_000_000,
            q in proptest::sample::select(QS.to_vec()),
        ) {
            // Past LONG_COEFFICIENT_BITS, with a factor the moduli may share.
            let scale = Int::from(3) * Int::from(2).pow(e) * Int::from(7).pow(200);
            let coeffs: [ZPoly; 5] = std::array::from_fn(|k| poly(&raw[k]).mul_int(&scale));
            prop_assume!(!coeffs[0].is_zero());
            let fresh = || Coefficients::new(CharPoly { coeffs: coeffs.clone() });
            let residues = fresh();
            prop_assert!(residues.long());
            let (formed, exact) = (fresh(), fresh());
            for end in [End::First, End::Last] {
                for modulus in [Int::from(m), Int::from(2).pow(e) * Int::from(3), Int::from(-m)] {
                    let x = exact.extreme(q, end).clone();
                    prop_assert!(formed.extreme(q, end) == &x);
                    let expected = x.is_zero() || x.is_divisible_by(&modulus);
                    prop_assert_eq!(residues.extreme_divisible_by(q, end, &modulus), expected);
                    prop_assert_eq!(formed.extreme_divisible_by(q, end, &modulus), expected);
                }
                prop_assert_eq!(fresh().extreme_is_zero(q, end), exact.extreme(q, end).is_zero());
                // Read off the formed polynomial.
                let read = fresh();
                read.polynomial(q);
                prop_assert!(read.extreme_at_hand(q, end));
                prop_assert_eq!(read.extreme(q, end), exact.extreme(q, end));
            }
        }

        /// The multi-precision sign is the exact closed form's whenever it
        /// decides: on long values, on values perturbed by `2^(−k)` of their
        /// size from a quartic with a double root (where `sr0` and maybe
        /// others cancel to that size), and never on the exact double root.
        #[test]
        fn interval_sign_is_the_exact_sign(
            limbs in proptest::collection::vec(proptest::collection::vec(any::<u64>(), 1..60), 5),
            neg in proptest::array::uniform5(any::<bool>()),
            roots in proptest::array::uniform3(-50i64..50),
            k in 0u64..1400,
            q in proptest::sample::select(QS.to_vec()),
        ) {
            let long: [Int; 5] = std::array::from_fn(|i| Int::from_u64_limbs(neg[i], &limbs[i]));
            // 2^1600·(λ − r₀)²(λ − r₁)(λ − r₂), every coefficient an integer.
            let r = |i: usize| Rat::from(roots[i]);
            let double = quartic(&Rat::from_int(Int::one().shl(1600)), &[r(0), r(0), r(1), r(2)], &[])
                .map(|c| c.numer().clone());
            let perturbed: [Int; 5] = std::array::from_fn(|i| &double[i] + &long[i].shr_floor(k.min(long[i].bits())));
            for values in [&long, &perturbed] {
                let exact = closed_form(values, q).unwrap().signum();
                if let Some(s) = interval_sign(values, q) {
                    prop_assert_eq!(s, exact);
                }
            }
            if q == Quantity::Sr0 {
                prop_assert_eq!(interval_sign(&double, q), None);
            }
        }
    }

    /// Long values that do not cancel are decided without the exact form.
    #[test]
    fn interval_sign_decides_long_values() {
        let values = [3i64, -7, 11, 5, -13].map(|v| Int::from(v).shl(2000) + Int::from(v));
        for q in QS {
            let exact = closed_form(&values, q).unwrap().signum();
            assert_eq!(interval_sign(&values, q), Some(exact), "{q:?}");
        }
    }

    /// An interval with an exact zero, huge, infinite or ordinary ends.
    fn any_interval() -> impl Strategy<Value = Interval> {
        let end = prop_oneof![
            Just(0.0),
            Just(-0.0),
            Just(f64::INFINITY),
            Just(f64::NEG_INFINITY),
            Just(1e300),
            Just(-1e300),
            -10.0f64..10.0,
            -1e-300f64..1e-300,
        ];
        (end.clone(), end).prop_map(|(a, b)| Interval::new(a.min(b), a.max(b)))
    }

    /// A jet: of a polynomial (`f′ = 0` exactly only with `f″ = 0`), or
    /// with `f′` the exact zero and `f″` not.
    fn leaf() -> impl Strategy<Value = Jet2<Interval>> {
        let zero = Interval::point(0.0);
        (any_interval(), any_interval(), any_interval(), 0..5).prop_map(move |(v, d, dd, kind)| {
            match kind {
                0 => Jet2 {
                    v,
                    d: zero,
                    dd: zero,
                },
                1 => Jet2 { v, d, dd: zero },
                // `f′` the exact zero with `f″` not: what the ring
                // operations of `Interval` may compute (a cancellation).
                2 => Jet2 { v, d: zero, dd },
                _ => Jet2 { v, d, dd },
            }
        })
    }

    fn bits(i: Interval) -> (u64, u64) {
        (i.lo.to_bits(), i.hi.to_bits())
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2000))]
        /// The closed forms over flat jets are those over nested dual
        /// numbers bit for bit (both copies of the first derivative),
        /// with exact zeros, infinities and NaN-born whole lines.
        #[test]
        fn jets_are_the_nested_duals(leaves in proptest::array::uniform5(leaf())) {
            let nested = leaves.map(|j| Dual { v: Dual { v: j.v, d: j.d }, d: Dual { v: j.d, d: j.dd } });
            for q in [Quantity::Sr22, Quantity::Sr20, Quantity::Sr11, Quantity::Sr10, Quantity::Sr0] {
                let flat = closed_form(&leaves, q).expect("a closed form");
                let deep = closed_form(&nested, q).expect("a closed form");
                prop_assert_eq!(bits(flat.v), bits(deep.v.v));
                prop_assert_eq!(bits(flat.d), bits(deep.v.d));
                prop_assert_eq!(bits(flat.d), bits(deep.d.v));
                prop_assert_eq!(bits(flat.dd), bits(deep.d.d));
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]
        /// The formed closed forms are those over `Z[t]`, whichever route
        /// formed them: short coefficients (the `i128` route, up to its
        /// limit: 16 bits for `sr0`, products of up to 8 terms) and long
        /// ones.
        #[test]
        fn formed_polynomials_are_the_closed_forms(
            raw in proptest::collection::vec(proptest::collection::vec(any::<i64>(), 1..8), 5),
            bits in prop_oneof![Just(8u64), Just(16), Just(25), Just(40), Just(90)],
        ) {
            let coeffs: [ZPoly; 5] = std::array::from_fn(|k| {
                ZPoly::new(raw[k].iter().map(|&c| {
                    // About `bits` bits: a shift right, or left past 64.
                    if bits <= 64 { Int::from(c >> (64 - bits)) } else { Int::from(c).shl(bits - 64) }
                }).collect())
            });
            let f = Coefficients::new(CharPoly { coeffs: coeffs.clone() });
            for q in [Quantity::Sr22, Quantity::Sr20, Quantity::Sr11, Quantity::Sr10, Quantity::Sr0] {
                prop_assert_eq!(f.polynomial(q), &closed_form(&coeffs, q).expect("a polynomial"));
            }
        }

        /// Each model agrees with the polynomial it stands for: exact signs
        /// and values at points, and enclosures that hold the exact values.
        /// `tilt` scales the coefficient of `λ^k` by `2^(tilt·k)` (or, when
        /// negative, by `2^(|tilt|·(4 − k))`): sizes apart by up to `2^800`,
        /// where the double-word jet must still enclose the exact values,
        /// and may decline only values beyond `f64`'s range.
        #[test]
        fn models_agree_with_the_closed_form_polynomials(
            raw in proptest::collection::vec(proptest::collection::vec(-40i64..40, 1..5), 5),
            a in -64i64..64, j in 0u64..8, b in 1i64..9, tilt in -200i64..200,
        ) {
            // Coefficient i (high → low) is that of λ^(4 − i).
            // A negative tilt makes the low powers the large ones.
            let lift = |i: u64| if tilt >= 0 { tilt as u64 * (4 - i) } else { tilt.unsigned_abs() * i };
            let coeffs: [ZPoly; 5] = std::array::from_fn(|k| {
                ZPoly::new(poly(&raw[k]).coeffs().iter().map(|c| c.shl(lift(k as u64))).collect())
            });
            let cp = CharPoly { coeffs: coeffs.clone() };
            let f = Rc::new(Coefficients::new(cp));
            let inv = closed_forms(&coeffs);
            let m = Rat::dyadic(Int::from(a), j);
            let x = Rat::from_frac(a, b);
            for q in [Quantity::Sr22, Quantity::Sr20, Quantity::Sr11, Quantity::Sr10] {
                let model = model(&f, q);
                let exact = inv.get(q).expect("a polynomial");
                // The image modulo the word prime from the f_k's images
                // (before q is formed) is q's, and a degree it claims kept is q's.
                let (image, kept) = model.residues();
                prop_assert_eq!(&image, &Residues::of(exact));
                prop_assert!(!kept || image.degree() == exact.degree());
                prop_assert_eq!(model.exact(), exact);
                prop_assert_eq!(model.sign_at(&x), exact.sign_at(&x));
                let sigma = |v: Rat| v.mul_pow2(-f.sigma_exp(q));
                let (v, d) = model.value_and_slope_at(&m);
                let holds = |iv: Interval, r: Rat| {
                    Rat::from_f64_exact(iv.lo).expect("finite") <= r
                        && r <= Rat::from_f64_exact(iv.hi).expect("finite")
                };
                prop_assert!(holds(v, sigma(exact.eval_rat(&m))));
                prop_assert!(holds(d, sigma(exact.derivative().eval_rat(&m))));
                // The double-word jet holds the same values, on the exact
                // jet's exponent.
                // (None only for values beyond f64's range, here 2^±800.)
                let (value, slope) = (sigma(exact.eval_rat(&m)), sigma(exact.derivative().eval_rat(&m)));
                let log2 = |r: &Rat| r.numer().bits() as i64 - r.denom().bits() as i64;
                let in_range = |r: &Rat| r.is_zero() || log2(r).abs() < 800;
                let ball = model.ball_jet_at(&m);
                prop_assert!(ball.is_some() || !(in_range(&value) && in_range(&slope)), "{:?} at {}", q, m);
                if let Some(ball) = ball {
                    let in_ball = |b: DwBall, r: &Rat| b.ends().is_some_and(|(lo, hi)| lo <= *r && *r <= hi);
                    prop_assert!(in_ball(ball.value, &value));
                    prop_assert!(in_ball(ball.slope, &slope));
                    prop_assert_eq!(ball.slope_exp, model.exact_jet_at(&m).slope_exp);
                }
                // The cheaper jet over an interval around m: the value at
                // m, on the jet's exponents, and a slope that holds q′ at m
                // and at both ends (the mean value form reads it anywhere
                // in the interval).
                let (lo, hi) = (&m - &Rat::from_frac(1, 16), &m + &Rat::from_frac(1, 16));
                let around = Interval::from_rat(&lo).hull(&Interval::from_rat(&hi));
                if let Some(cheap) = model.ball_value_and_slope_over(&m, around) {
                    let in_ball = |b: DwBall, r: &Rat| b.ends().is_some_and(|(lo, hi)| lo <= *r && *r <= hi);
                    prop_assert!(in_ball(cheap.value, &value), "{:?} at {}", q, m);
                    for at in [&lo, &m, &hi] {
                        prop_assert!(in_ball(cheap.slope, &sigma(exact.derivative().eval_rat(at))), "{:?} at {}", q, at);
                    }
                    let jet = model.exact_jet_at(&m);
                    prop_assert_eq!((cheap.value_exp, cheap.slope_exp), (jet.value_exp, jet.slope_exp));
                }
                // (None is allowed where the point jet is known: a slope
                // over the interval may leave f64's range; the step then
                // takes the jet.)
                // The value-only ball's sign, where it decides, is the
                // exact one; and it decides wherever the jet's value does.
                let sign = model.ball_sign_at(&m);
                prop_assert!(sign.is_none() || sign == Some(exact.sign_at(&m)), "{:?} at {}", q, m);
                let jet_sign = ball.and_then(|b| b.value.sign()).filter(|s| *s != 0);
                prop_assert!(jet_sign.is_none() || sign == jet_sign, "{:?} at {}", q, m);
                let point = Interval::from_rat(&m);
                if point.lo == point.hi {
                    prop_assert!(holds(model.enclose(point), sigma(exact.eval_rat(&m))));
                    let second = exact.derivative().derivative().eval_rat(&m);
                    prop_assert!(holds(model.enclose_second(point), sigma(second)));
                }
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// Roots of each closed form, isolated and refined through its
        /// model (the step past the float resolution from the model's
        /// cheaper jet, its cuts signed by the mean value form, else from
        /// the double-word jet, its cuts signed by value-only balls, and the
        /// exact steps below it): every enclosure meets the target and
        /// holds a sign change of the exact polynomial (or is its exact
        /// root), at `10^(−15)` and `10^(−40)`, with the coefficients' sizes
        /// up to `2^800` apart (`tilt`, as above).
        #[test]
        fn closed_form_roots_refine_to_enclosures_of_the_exact_roots(
            raw in proptest::collection::vec(proptest::collection::vec(-40i64..40, 1..5), 5),
            tilt in -200i64..200, deep in any::<bool>(),
        ) {
            let lift = |i: u64| if tilt >= 0 { tilt as u64 * (4 - i) } else { tilt.unsigned_abs() * i };
            let coeffs: [ZPoly; 5] = std::array::from_fn(|k| {
                ZPoly::new(poly(&raw[k]).coeffs().iter().map(|c| c.shl(lift(k as u64))).collect())
            });
            let f = Rc::new(Coefficients::new(CharPoly { coeffs: coeffs.clone() }));
            let inv = closed_forms(&coeffs);
            let target = Rat::new(Int::one(), Int::pow10(if deep { 40 } else { 15 })).expect("nonzero");
            let (zero, one) = (Rat::zero(), Rat::one());
            for q in [Quantity::Sr22, Quantity::Sr20, Quantity::Sr11, Quantity::Sr10, Quantity::Sr0] {
                let exact = inv.get(q).expect("a polynomial");
                // The model's function must be squarefree, of positive degree.
                if exact.degree().unwrap_or(0) == 0 || exact.squarefree_part().degree() != exact.degree() {
                    continue;
                }
                let b = ccd_poly::Bernstein::from_power(exact, &zero, &one);
                let sign = b.scale().signum();
                let enclosed: Vec<Interval> = b
                    .coeffs()
                    .iter()
                    .map(|c| Interval::from_int(&(c * &Int::from(sign))))
                    .collect();
                for mut root in ccd_solver::RootIter::filtered(model(&f, q), &zero, &one, &enclosed) {
                    root.refine_to(&target);
                    prop_assert!(root.width() <= target, "{:?}: {}", q, root.width());
                    let (lo, hi) = (root.lo(), root.hi());
                    let held = if lo == hi {
                        exact.sign_at(lo) == 0
                    } else {
                        exact.sign_at(lo) * exact.sign_at(hi) < 0
                    };
                    prop_assert!(held, "{:?}: [{}, {}]", q, lo, hi);
                }
            }
        }
    }

    proptest! {
        // Cheap cases (about a fifth reach a triple-root hint).
        #![proptest_config(ProptestConfig::with_cases(256))]
        /// `sr0 ≡ 0` decided without forming `sr0` is the formed answer. The
        /// pairs are built as `f = h(λ)^e·Σ_j t^j·g_j(λ)` (degree 4 in `λ`)
        /// with `e = 2` (a repeated factor common to every `t`, so
        /// `sr0 ≡ 0`: the claim the shortcut rests on, checked on the
        /// formed `sr0`), `e = 1` (only a common simple factor) or, with
        /// `plain`, without `h` (`F_j = (λ² + (j + 1)λ + 1)·g_j`); shifts of
        /// 0..16 bits (short numbers, within the `i128` route's 16 bits, at
        /// the low end) or of 17..119 (past them). Where one `g_j` has no
        /// repeated factor (and none shared with `h`), the test must find
        /// `h` (it is complete there); and `g_0 = k²` (a repeated factor of
        /// `F_0` alone, bodies touching at `t = 0`) must not hide it.
        #[test]
        fn sr0_vanishing_without_forming_it_is_the_formed_answer(
            h in proptest::collection::vec(-9i64..10, 2),
            g in proptest::collection::vec(proptest::collection::vec(-9i64..10, 3), 1..4),
            e in 1u32..3, plain in any::<bool>(), touch in any::<bool>(),
            shift in prop_oneof![0u64..17, 17u64..120],
        ) {
            let h = poly(&h);
            prop_assume!(h.degree() == Some(1));
            let mut g: Vec<ZPoly> = g.iter().map(|c| poly(c)).collect();
            if touch {
                // F_0 = h^e·k² with k = λ + 3: a root of F_0 alone.
                g[0] = poly(&[9, 6, 1]).mul_int(&g[0].coeffs().first().cloned().unwrap_or_else(Int::one));
            }
            let factor = if plain { ZPoly::one() } else { h.pow(e) };
            let lambda_deg = 4 - if plain { 0 } else { e as usize };
            // F_j(λ), constant term first, padded to λ^4 by x^(4 − e − 2)·g_j.
            let parts: Vec<ZPoly> = g.iter().enumerate().map(|(j, gj)| {
                let top = if plain {
                    poly(&[1, j as i64 + 1, 1])
                } else {
                    ZPoly::monomial(Int::from(j as i64 + 1), lambda_deg - 2)
                };
                &factor * &(&top * gj)
            }).collect();
            let coeffs: [ZPoly; 5] = std::array::from_fn(|k| {
                // Coefficient of λ^(4 − k), a polynomial in t.
                ZPoly::new(parts.iter().map(|p| p.coeff(4 - k).shl(shift)).collect())
            });
            let f = Coefficients::new(CharPoly { coeffs: coeffs.clone() });
            let formed = closed_form(&coeffs, Quantity::Sr0).expect("a polynomial");
            if !plain && e == 2 {
                prop_assert!(formed.is_zero());
                let clean = g.iter().any(|gj| {
                    let p = &h * gj;
                    gj.degree() == Some(2) && p.gcd(&p.derivative()).degree() == Some(0)
                });
                // The shortcut itself (not the formed fallback) finds h,
                // except for an f constant in t, which it leaves alone.
                prop_assert!(f.vanishes_identically(Quantity::Sr0));
                let found = f.fixed.get().is_some_and(Option::is_some);
                prop_assert!(found || !clean || f.f.degree() == 0, "h = {:?}, g = {:?}", h, g);
                // Where f = h²·g gains a triple root, sr11 vanishes doubly:
                // the hint for sr11's squarefree part holds.
                if let Some(triple) = f.triple_root_instants() {
                    let sr11 = closed_form(&coeffs, Quantity::Sr11).expect("a polynomial");
                    prop_assert!(sr11.is_zero() || sr11.div_exact(&(&triple * &triple)).is_some());
                }
            }
            prop_assert_eq!(f.vanishes_identically(Quantity::Sr0), formed.is_zero());
            prop_assert_eq!(f.proven_zero(Quantity::Sr0), formed.is_zero());
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// The multi-precision jet of long values holds `σ·q(m)` and
        /// `σ·q′(m)` on the exact jet's exponents, far past `f64`'s range
        /// (coefficients lifted by 1600–2600 bits), at any precision it
        /// offers; short values get none.
        #[test]
        fn big_jets_hold_the_exact_jets(
            raw in proptest::collection::vec(proptest::collection::vec(-40i64..40, 1..5), 5),
            a in -64i64..64, j in 0u64..8, lift in 1600u64..2600, prec in 64u32..600,
            short in any::<bool>(),
        ) {
            let lift = if short { 0 } else { lift };
            let coeffs: [ZPoly; 5] = std::array::from_fn(|k| {
                ZPoly::new(poly(&raw[k]).coeffs().iter().map(|c| c.shl(lift * (4 - k as u64))).collect())
            });
            let f = Rc::new(Coefficients::new(CharPoly { coeffs: coeffs.clone() }));
            let m = Rat::dyadic(Int::from(a), j);
            for q in QS {
                let model = model(&f, q);
                let exact = model.exact_jet_at(&m);
                let Some(big) = model.big_jet_at(&m, prec) else {
                    continue;
                };
                prop_assert!(!short);
                prop_assert_eq!((big.value_exp, big.slope_exp), (exact.value_exp, exact.slope_exp));
                let holds = |b: &BigInterval, v: &Int, e: i64| {
                    let r = Rat::from_int(v.clone()).mul_pow2(-e);
                    b.lo_rat() <= r && r <= b.hi_rat()
                };
                prop_assert!(holds(&big.value, &exact.value, exact.value_exp));
                prop_assert!(holds(&big.slope, &exact.slope, exact.slope_exp));
            }
        }
    }
}
