//! [`RealRoot`]: a real algebraic number given by a squarefree function
//! (an integer polynomial, or any [`SignModel`] of one) and an isolating
//! interval with exact rational ends; refinable to any width, and able to
//! decide the exact sign of any polynomial at it.

use crate::ball::{JetBall, Scaled};
use crate::local::{Cost, Local};
use crate::model::{BallJet, ExactJet, SignModel, SignProbe};
use ccd_arith::{sign_variations, Int, Interval, Rat, RingOps};
use ccd_poly::{Bernstein, ZPoly};
use std::sync::Arc;

/// The round of [`RealRoot::sign_with`] from which, once `q(α) ≠ 0` is
/// proven, the exact Bernstein test on `q` runs besides the enclosures.
const EXACT_SIGN_ROUND: u32 = 3;

/// The `−log2` of the width down to which [`RealRoot::sign_with`]
/// narrows an enclosure before its first Taylor forms: on a wider one
/// (an isolating interval, typically `2^(−2)`…`2^(−9)` of the span) their
/// remainder, which grows with the squared width, seldom decides, and the
/// two enclosures they need cost about what the narrowing does, which the
/// sign then needs anyway (affine-deg2: 18 signs at 6 roots, of which 11
/// reached the Taylor forms there and 5 decided).
pub(crate) const WIDE_SIGN_LOG2: i64 = 10;

/// `−log2` of a positive rational, rounded up (within one bit), from bit
/// lengths alone.
fn neg_log2(r: &Rat) -> i64 {
    (r.denom().bits() as i64 - r.numer().bits() as i64 + 1).max(0)
}

/// The exponent `k` of an exact Newton step's grid `2^(−k)` from the `−log2`
/// of `w²`, of the target and of `w`, and the model's reach `model_k`:
/// about `max(w², target/4)`, no finer than the reach, and at least `w/4`.
fn step_grid(w_sq: i64, target: i64, model_k: i64, w: i64) -> i64 {
    w_sq.min(target + 2).min(model_k).max(w + 2)
}

/// The exponent `k` of an exact Newton step's grid `2^(−k)` (see
/// [`RealRoot::exact_newton_jump`]): [`step_grid`] with the Taylor
/// model's reach (`sup|p″|·w²/|p′|`, from the slope's `f64` enclosure
/// `slope` and `second ⊇ p″(I)`).
fn newton_exponent(w: &Rat, target: &Rat, slope: Interval, second: Interval) -> i64 {
    // The model's remainder at any cut is below sup|p″(I)|·w²/2, and a
    // cut δ from the root has a linear part near |p′|·δ: cuts closer
    // than `reach` would need exact evaluations, so when the model
    // reaches well inside the enclosure the cuts go no closer.
    let w_f = w.to_f64();
    let reach =
        second.lo.abs().max(second.hi.abs()) * w_f * w_f / slope.lo.abs().min(slope.hi.abs());
    let model_k = if !slope.contains_zero() && reach > 0.0 && reach < w_f / 16.0 {
        (-reach.log2()).floor() as i64
    } else {
        i64::MAX
    };
    step_grid(neg_log2(&(w * w)), neg_log2(target), model_k, neg_log2(w))
}

/// The sign of `q` on `[lo, hi]` by Descartes' rule: `Some` when `q`'s
/// exact Bernstein coefficients there have no sign variation and the
/// first is nonzero (then `q` has no root in `[lo, hi]`).
pub(crate) fn descartes(q: &ZPoly, lo: &Rat, hi: &Rat) -> Option<i32> {
    let b = Bernstein::signs_of_power(q, lo, hi);
    (sign_variations(b.iter().copied()) == 0 && b[0] != 0).then(|| b[0])
}

/// `[lo, hi]` (of width `width`) rounded outward to the grid `2^(−k)`,
/// `k` two bits past its width's, when that makes the ends markedly
/// shorter (a quarter of their bits or more); `None` otherwise. A root
/// narrowed by Newton steps next to a cluster can have ends four times as
/// long as its width needs, and the Bernstein coefficients' cost grows
/// with the ends' bits.
pub(crate) fn short_ends(lo: &Rat, hi: &Rat, width: &Rat) -> Option<(Rat, Rat)> {
    let k = neg_log2(width) + 2;
    let bits = |x: &Rat| x.numer().bits() + x.denom().bits();
    // The grid's ends have about `2k` bits each (below 1 in size): skip
    // the rounding where it cannot shorten them enough.
    let long = bits(lo) + bits(hi);
    if 3 * long < 16 * k as u64 {
        return None;
    }
    let lo_k = Rat::dyadic(lo.mul_pow2(k).floor(), k as u64);
    let hi_k = Rat::dyadic(-(-hi.mul_pow2(k)).floor(), k as u64);
    (4 * (bits(&lo_k) + bits(&hi_k)) <= 3 * long).then_some((lo_k, hi_k))
}

/// [`descartes`] on `[lo, hi]`, tried first on its [`short_ends`]. No
/// variation over that wider interval means none over `[lo, hi]`
/// (subdivision diminishes variation), and the first coefficients have
/// the same sign, as `q` has no root between the two left ends: so it
/// decides only where the test over `[lo, hi]` would, as it would.
pub(crate) fn descartes_sign(q: &ZPoly, lo: &Rat, hi: &Rat, width: &Rat) -> Option<i32> {
    short_ends(lo, hi, width)
        .and_then(|(l, h)| descartes(q, &l, &h))
        .or_else(|| descartes(q, lo, hi))
}

/// The most steps of one narrowing between two rounds of
/// [`RealRoot::sign_with`]. A round asks for twice the bits of the last,
/// as exact Newton steps double them; next to a close cluster of roots
/// Newton gains about one bit a step, and a round asking for 2,048 bits
/// there took 380 exact evaluations of a degree-96 `p` past the 3,360
/// bits that decided the sign (`seed-73-case-19535`, 16.8 s). With a
/// budget the sign is tried again after at most this many steps. No
/// narrowing of a shipped scene takes more than 15.
pub(crate) const SIGN_NARROW_STEPS: u32 = 32;

/// The precision of [`RealRoot::sign_with`]'s multi-precision round
/// ([`SignModel::big_jet_at`]): the round needs `q(m)` and `q′(m)` only to
/// a few bits past the Taylor remainder, and values that cancel further
/// take the exact jet (or, from a model that raises the precision while
/// its value holds zero, [`SignProbe`]'s re-centred one, more bits).
const SIGN_BALL_BITS: u32 = 128;

/// The bits beyond the step's grid of the multi-precision Newton jump
/// ([`RealRoot::exact_newton_jump`]): 32 and 96 pinned fewer steps or
/// cost more (`ratio-disc-k0064-overlap` 55.5M and 54.6M against 52.6M).
const NEWTON_BALL_MARGIN: u32 = 64;

/// `1 ± 2^(−50)`: past the roundings of a product of a few `f64` factors
/// (each off by at most `2^(−53)` relatively), upwards and downwards.
const UP4: f64 = 1.0 + 4.0 * f64::EPSILON;
const DOWN4: f64 = 1.0 - 4.0 * f64::EPSILON;

/// The `f64` enclosure of the exact `σ·q(m)` (or `σ·q′(m)`), an integer
/// `N` over `2^exp` ([`ExactJet::enclose`]), when the ball of it pins that
/// enclosure down: every integer the ball allows has the same sign and the
/// same leading 64 bits, which is all `Interval::from_int_scaled` reads.
fn pinned<B: JetBall>(ball: &B, exp: i64) -> Option<Interval> {
    let (lo, hi) = ball.end_points()?;
    let (n_min, n_max) = (-(-lo.mul_pow2(exp)).floor(), hi.mul_pow2(exp).floor());
    (n_min.signum() == n_max.signum() && n_min.top_bits() == n_max.top_bits())
        .then(|| Interval::from_int_scaled(&n_min, exp))
}

/// `⌊a − 2^k·q(m)/q′(m)⌋` (`a = 2^k·m`) from a ball jet at `m`, when the
/// slope's ball excludes zero and both ends of the quotient's ball give the
/// same floor (then it is the exact jet's, [`exact_step_floor`]); `None`
/// otherwise.
fn step_floor<B: JetBall>(a: &Rat, k: i64, jet: &BallJet<B>) -> Option<Int> {
    jet.slope.sign_of().filter(|s| *s != 0)?;
    let (dl, dh) = jet.value.quotient(&jet.slope)?.scaled(k).end_points()?;
    let n = (a - &dh).floor();
    (n == (a - &dl).floor()).then_some(n)
}

/// [`step_floor`] in `f64`, for a double-word jet at an `f64` point `x`
/// with `|2^k·x| < 2^53`: the integer part `w` and the fraction `f` of
/// `2^k·x` are then exact, and `⌊f − 2^k·δ⌋` is read off the quotient
/// ball's rounded-outward `f64` ends, each subtraction widened by an ulp,
/// when both give the same integer `e` (then `n = w + e`, the exact jet's);
/// `None` otherwise, where the rational ends decide. No rational is formed.
fn step_floor_f64(x: f64, k: i64, jet: &BallJet) -> Option<Int> {
    jet.slope.sign().filter(|s| *s != 0)?;
    let d = jet.value.quotient(&jet.slope)?.scaled(k);
    // 2^k·x exactly (a power-of-two scaling; inf or NaN past the range).
    let a = x * 2f64.powi(i32::try_from(k).ok()?.min(1100));
    if !a.is_finite() || a.abs() >= 2f64.powi(53) {
        return None;
    }
    let whole = a.floor();
    let frac = a - whole;
    let (lo, hi) = ((frac - d.upper()).next_down(), (frac - d.lower()).next_up());
    let e = lo.floor();
    (e == hi.floor() && e.abs() < 2f64.powi(53))
        .then(|| &Int::from(whole as i64) + &Int::from(e as i64))
}

/// `⌊2^k·(m − q(m)/q′(m))⌋` at the dyadic `m = x` from a double-word jet
/// there: [`step_floor_f64`], else [`step_floor`] on the rational ends.
fn ball_step_floor(x: f64, m: &Rat, k: i64, jet: &BallJet) -> Option<Int> {
    step_floor_f64(x, k, jet).or_else(|| step_floor(&m.mul_pow2(k), k, jet))
}

/// `⌊2^k·(m − q(m)/q′(m))⌋` from the exact jet at the dyadic `m = a/2^j`
/// (`q′(m) ≠ 0`): `(a·S·2^(k−j) − V·2^(k+s−v))/S` over a common power of
/// two that keeps every exponent nonnegative, one integer division.
fn exact_step_floor(m: &Rat, k: i64, jet: &ExactJet) -> Int {
    let j = m.dyadic_exponent().expect("a dyadic point") as i64;
    let (v, s) = (jet.value_exp, jet.slope_exp);
    let lift = 0.max(j - k).max(v - s - k);
    let shl = |x: &Int, e: i64| x.shl(e as u64);
    (shl(&(m.numer() * &jet.slope), k - j + lift) - shl(&jet.value, k + s - v + lift))
        .div_floor(&shl(&jet.slope, lift))
}

/// The Taylor remainder `ρ = sup|q″(I)|·r²/2` of one ball round
/// ([`RealRoot::ball_round`]) and the ends of the `f64` test's remainder
/// `[min(0, q″⁻), max(0, q″⁺)]·r²/2`, each rounded to the safe side.
struct Remainders {
    /// `ρ` rounded up.
    up: Scaled,
    /// `ρ` rounded down.
    down: Scaled,
    /// `−min(0, q″⁻)·r²/2 ≥ 0`, rounded toward zero.
    minus_lo: Scaled,
    /// `−max(0, q″⁺)·r²/2 ≤ 0`, rounded toward zero.
    minus_hi: Scaled,
}

impl Remainders {
    /// From `bound ≥ sup|q″(I)|`, `r_dn ≤ r ≤ r_up` and `second ⊇ q″(I)`:
    /// with `wide` (balls that reach past `f64`'s exponent range) as
    /// [`Scaled`] products, which keep their size however small; else in
    /// `f64`, where an underflow only loses what is far below any
    /// double-word ball's value (at least `2^(−900)`).
    fn new(bound: f64, r_up: f64, r_dn: f64, second: Interval, wide: bool) -> Remainders {
        let (lo, hi) = (-second.lo.min(0.0), -second.hi.max(0.0));
        if wide {
            let (r_up, r_dn) = (Scaled::new(r_up), Scaled::new(r_dn));
            let half_sq_up = r_up.times(r_up).times(Scaled::new(0.5 * UP4));
            let half_sq_dn = r_dn.times(r_dn).times(Scaled::new(0.5 * DOWN4));
            let down = |x: f64| Scaled::new(x).times(half_sq_dn).times(Scaled::new(DOWN4));
            return Remainders {
                up: Scaled::new(bound).times(half_sq_up).times(Scaled::new(UP4)),
                down: down(bound),
                minus_lo: down(lo),
                minus_hi: down(hi),
            };
        }
        // r²/2 rounded up and down (three roundings, and underflow).
        let half_sq_up = r_up * r_up * 0.5 * UP4 + f64::MIN_POSITIVE;
        let half_sq_dn = (r_dn * r_dn * 0.5 * DOWN4 - f64::MIN_POSITIVE).max(0.0);
        Remainders {
            up: Scaled::exact(bound * half_sq_up * UP4 + f64::MIN_POSITIVE),
            down: Scaled::exact(bound * half_sq_dn * DOWN4),
            minus_lo: Scaled::exact(((lo * half_sq_dn) * DOWN4 - f64::MIN_POSITIVE).max(0.0)),
            minus_hi: Scaled::exact(((hi * half_sq_dn) * DOWN4 + f64::MIN_POSITIVE).min(0.0)),
        }
    }
}

/// [`RealRoot::sign_with`]'s Taylor test in `f64`, from the `f64`
/// enclosures `qm`, `dqm` of `σ·q(m)`, `σ·q′(m)` and the exact offsets
/// `(ol, oh)` of the enclosure's ends from `m`: `q(m) + q′(m)·(I − m) +
/// q″(I)·(I − m)²/2`, with `I − m` enclosed from the exact offsets (an
/// `f64` interval around `α` itself could not be narrower than an ulp of
/// `α`). Also what a ball round runs where its balls pin `qm` and `dqm`
/// down, so that both are the same test.
fn float_taylor((ol, oh): (&Rat, &Rat), qm: Interval, dqm: Interval, second: Interval) -> Interval {
    let offset = Interval::from_rat(ol).hull(&Interval::from_rat(oh));
    qm + dqm * offset + second * offset.square() * Interval::point(0.5)
}

/// What one round of Taylor tests from balls found
/// ([`RealRoot::ball_round`]).
enum BallRound {
    /// The sign of `q(α)`, proven.
    Sign(i32),
    /// Neither exact Taylor test decides this round; `value_zero` when
    /// the balls prove whether the `f64` enclosure of the exact `q(m)`
    /// holds zero (the zero test's trigger in round 0), `None` when they
    /// cannot tell.
    Open { value_zero: Option<bool> },
}

/// The sign of an enclosure that excludes zero.
fn decided(iv: Interval) -> Option<i32> {
    iv.sign().filter(|s| *s != 0)
}

/// What [`RealRoot::sign_within`] carries from round to round besides the
/// enclosure.
#[derive(Default)]
struct SignState {
    /// Once `q(α) ≠ 0` is proven (`q` itself is formed only if the
    /// Bernstein test runs, or for a gcd the images cannot prove).
    nonzero: bool,
    /// `q` re-centred next to the enclosure once an exact evaluation of
    /// it there is costly (`LOCAL_WORTH`).
    near: Option<Option<Local>>,
}

/// Newton's iteration for `p` in `f64` from the middle of `[lo, hi]`
/// (each step clamped to it): up to [`FLOAT_NEWTON_STEPS`] steps, stopping
/// at a fixed point; the last point and the slope evaluated before it, or
/// `None` at a zero or non-finite value or slope.
///
/// Near the root the rounded steps usually settle into a cycle of a few
/// points an ulp or so apart (period 2 to 4 on the benchmark scenes) that
/// never reaches a fixed point. The step is a function of the point alone
/// (`value_and_slope` is), so once a point comes back the rest of the
/// sequence repeats: the point and slope after all the steps are read off
/// the cycle, the very ones the steps would have reached, without
/// evaluating them.
pub(crate) fn float_newton(
    lo: f64,
    hi: f64,
    value_and_slope: impl Fn(f64) -> (f64, f64),
) -> Option<(f64, f64)> {
    // Points x_0, x_1, … and the slope at each.
    let mut seen = [(0.0f64, 0.0f64); FLOAT_NEWTON_STEPS];
    let mut x = 0.5 * (lo + hi);
    for i in 0..FLOAT_NEWTON_STEPS {
        let (v, d) = value_and_slope(x);
        if d == 0.0 || !v.is_finite() || !d.is_finite() {
            return None;
        }
        seen[i] = (x, d);
        let nx = (x - v / d).clamp(lo, hi);
        if nx == x {
            return Some((x, d));
        }
        // x_{i+1} = x_j: from j on, period i + 1 − j. The steps would end
        // at x_N (N = FLOAT_NEWTON_STEPS) with the slope at x_{N−1}.
        if let Some(j) = seen[..i]
            .iter()
            .position(|&(y, _)| y.to_bits() == nx.to_bits())
        {
            let at = |k: usize| seen[j + (k - j) % (i + 1 - j)];
            return Some((at(FLOAT_NEWTON_STEPS).0, at(FLOAT_NEWTON_STEPS - 1).1));
        }
        x = nx;
    }
    // All the steps taken: x_N, with the slope at x_{N−1}.
    Some((x, seen[FLOAT_NEWTON_STEPS - 1].1))
}

/// The most steps of [`float_newton`].
const FLOAT_NEWTON_STEPS: usize = 12;

/// What a float Newton jump achieved.
enum Jump {
    /// The enclosure at least halved (or the root turned out exact).
    Progress,
    /// No progress, with the enclosure still wide: Newton's guess was off.
    Failed,
    /// No progress because the enclosure is at the root's float resolution.
    AtResolution,
    /// Progress, to the root's float resolution (the cuts at `eps` from
    /// the guess, not at the target's): a further jump would find it
    /// there.
    Resolved,
}

/// A real root `α` of a squarefree `p` (the function of a [`SignModel`]
/// `M`; by default an explicit polynomial in `ℤ[t]`): either known exactly
/// (`lo = hi = α`, a rational root) or the only root of `p` in the open
/// interval `(lo, hi)`, where `p(lo)` and `p(hi)` are nonzero with opposite
/// signs.
#[derive(Clone, Debug)]
pub struct RealRoot<M: SignModel + Clone = Arc<SignProbe>> {
    base: M,
    lo: Rat,
    hi: Rat,
    /// Sign of `p(lo)`; 0 when the root is exact.
    sign_lo: i32,
    /// Whether a double-word Newton step has failed to pin down an exact
    /// one here ([`RealRoot::exact_newton_jump`], or the step of
    /// [`RealRoot::past_float_jump`], on a grid within the balls' reach):
    /// the steps after it are closer to the root, where `p(m)` cancels
    /// further, so they go straight to the multi-precision or exact jet. (A
    /// cue for speed only: the ball step decides only what the exact one
    /// would.)
    balls_fail: bool,
}

impl<M: SignModel + Clone> RealRoot<M> {
    pub(crate) fn exact(base: M, at: Rat) -> RealRoot<M> {
        RealRoot {
            base,
            lo: at.clone(),
            hi: at,
            sign_lo: 0,
            balls_fail: false,
        }
    }

    pub(crate) fn isolated(base: M, lo: Rat, hi: Rat, sign_lo: i32) -> RealRoot<M> {
        debug_assert!(sign_lo != 0 && lo < hi);
        RealRoot {
            base,
            lo,
            hi,
            sign_lo,
            balls_fail: false,
        }
    }

    /// Lower end of the enclosure.
    pub fn lo(&self) -> &Rat {
        &self.lo
    }
    /// Upper end of the enclosure.
    pub fn hi(&self) -> &Rat {
        &self.hi
    }
    /// The squarefree polynomial this is a root of (formed on first need
    /// when the model defines it implicitly).
    pub fn poly(&self) -> &ZPoly {
        self.base.exact()
    }
    /// The rational value when the root is known exactly.
    pub fn exact_value(&self) -> Option<&Rat> {
        (self.sign_lo == 0).then_some(&self.lo)
    }
    /// `hi − lo`.
    pub fn width(&self) -> Rat {
        &self.hi - &self.lo
    }
    /// The midpoint of the enclosure.
    pub fn midpoint(&self) -> Rat {
        Rat::midpoint(&self.lo, &self.hi)
    }

    /// Moves one end to `x` (strictly inside) according to `s`, the exact
    /// sign of `p(x)`; a zero makes the root exact.
    fn cut(&mut self, x: Rat, s: i32) {
        if s == 0 {
            self.lo = x.clone();
            self.hi = x;
            self.sign_lo = 0;
        } else if s == self.sign_lo {
            self.lo = x;
        } else {
            self.hi = x;
        }
    }

    /// Cuts a sliver `2^(−g)` of the width `w` off the end `lo`
    /// (`from_lo`) or `hi` (one sign evaluation); `true` if the root is in
    /// the sliver, which is then the enclosure.
    fn cut_sliver(&mut self, from_lo: bool, g: u64, w: &Rat) -> bool {
        let d = w.mul_pow2(-(g as i64));
        let x = if from_lo {
            &self.lo + &d
        } else {
            &self.hi - &d
        };
        let s = self.base.filtered_sign_at(&x);
        let inside = (s != self.sign_lo) == from_lo || s == 0;
        self.cut(x, s);
        inside
    }

    /// Halves the enclosure (one sign evaluation).
    pub fn bisect(&mut self) {
        if self.sign_lo != 0 {
            let m = self.midpoint();
            let s = self.base.filtered_sign_at(&m);
            self.cut(m, s);
        }
    }

    /// Tries to jump to an enclosure of width about `target` around a float
    /// Newton estimate `x`, the cuts proven by `f64` enclosures of `p`.
    ///
    /// The cuts go at `x ∓ eps` with `eps` no smaller than twice the float
    /// resolution of the root there (the width of the enclosure of `p(x)`
    /// over `|p′(x)|`): closer cuts could not be signed in `f64`, and exact
    /// signs this close to the root are [`RealRoot::exact_newton_jump`]'s
    /// job, which needs two exact evaluations for any number of bits.
    /// Progress with cuts at that floor rather than at the target's
    /// `target/4` is [`Jump::Resolved`]: another jump would only find the
    /// enclosure at the resolution (about 25K instructions a root for
    /// nothing).
    ///
    /// A target below that resolution is first tried in one step from `x`
    /// itself ([`RealRoot::past_float_jump`]: a jet at `x` and two signs,
    /// in double-word balls where they decide); the float cuts follow only
    /// where it leaves the enclosure wider than the target.
    fn newton_jump(&mut self, target: &Rat) -> Jump {
        let (mut lo_f, mut hi_f) = (self.lo.to_f64(), self.hi.to_f64());
        let Some((x, slope)) = float_newton(lo_f, hi_f, |x| self.base.approx_value_and_slope(x))
        else {
            return Jump::Failed;
        };
        let resolution = self.base.enclose(Interval::point(x)).width() / slope.abs();
        let quarter = target.to_f64() * 0.25;
        let eps = quarter
            .max(4.0 * f64::EPSILON * x.abs().max(f64::MIN_POSITIVE))
            .max(2.0 * resolution);
        if quarter < eps {
            if self.past_float_jump(x, 2.0 * eps, target) {
                return Jump::Progress;
            }
            // It may have moved an end.
            (lo_f, hi_f) = (self.lo.to_f64(), self.hi.to_f64());
        }
        let (Some(a0), Some(a1), Some(b0), Some(b1)) = (
            Rat::from_f64_exact(x - 2.0 * eps),
            Rat::from_f64_exact(x - eps),
            Rat::from_f64_exact(x + eps),
            Rat::from_f64_exact(x + 2.0 * eps),
        ) else {
            return Jump::Failed;
        };
        // The shortest dyadics near x ∓ eps.
        if self.cut_both(
            Rat::dyadic_in(&a0, &a1),
            Rat::dyadic_in(&b0, &b1),
            |root: &RealRoot<M>, x: &Rat| root.base.float_sign_at(x),
        ) {
            if quarter < eps {
                Jump::Resolved
            } else {
                Jump::Progress
            }
        } else if 8.0 * eps >= hi_f - lo_f {
            Jump::AtResolution
        } else {
            Jump::Failed
        }
    }

    /// One Newton step past the root's float resolution, from the `f64`
    /// Newton point `x` (a dyadic `m`), for a target `t` below that
    /// resolution: on the grid `g = 2^(−k)`, `2^(3−k) ≤ t`, with `n = ⌊(m −
    /// q(m)/q′(m))/g⌋` ([`RealRoot::newton_floor`]: double-word balls where
    /// they pin it down), the enclosure is cut at `(n − 2)·g` and `(n +
    /// 3)·g`, `5g < t` apart. Newton's error is quadratic in `m`'s, far
    /// below `g` next to a simple root, so the root is between the cuts,
    /// whose signs ([`RealRoot::cut_sign`]: a double-word ball of `q`,
    /// else exact) prove it. `true` when the enclosure is then at most `t`
    /// wide. One jet and two signs, where the float cuts at the resolution
    /// and [`RealRoot::exact_newton_jump`] from their enclosure took two
    /// float signs, a jet, an enclosure of `q″` and two signs.
    ///
    /// The step reaches about `(x − α)²·|q″/2q′|`, at best about the square
    /// of `x`'s ulp: it is not tried for a grid finer than `2^(−96)·|x|`
    /// (there both cuts would fall on one side of the root, and the
    /// double-word balls could not pin `n` anyway), which is left to the
    /// float cuts and the exact Newton steps, whose bits double.
    ///
    /// The step is first tried from the model's cheaper jet over `[x −
    /// reach, x + reach]` ([`SignModel::ball_value_and_slope_over`]: the
    /// value's double-word ball at `m` and the slope's `f64` enclosure over
    /// the whole reach, as the root's float resolution puts the cuts
    /// within it); where it pins `n` down, that is the same `n`, and a cut
    /// within the reach is signed by the mean value form `q(m) +
    /// q′(reach)·(c − m)` instead of an evaluation at it.
    fn past_float_jump(&mut self, x: f64, reach: f64, target: &Rat) -> bool {
        let k = neg_log2(target) + 3;
        if k as f64 > 96.0 - x.abs().max(f64::MIN_POSITIVE).log2() {
            return false;
        }
        let Some(m) = Rat::from_f64_exact(x) else {
            return false;
        };
        let over = Interval::new((x - reach).next_down(), (x + reach).next_up());
        let cheap = (!self.balls_fail)
            .then(|| self.base.ball_value_and_slope_over(&m, over))
            .flatten()
            .and_then(|jet| Some((ball_step_floor(x, &m, k, &jet)?, jet)));
        let (n, jet) = match cheap {
            Some((n, jet)) => (n, Some(jet)),
            None => match self.newton_floor(x, &m, k) {
                Some(n) => (n, None),
                None => return false,
            },
        };
        let mean_value = |x: &Rat| {
            let jet = jet.as_ref()?;
            let c = Interval::from_rat(x);
            if !(over.lo <= c.lo && c.hi <= over.hi) {
                return None;
            }
            let d = jet.value.enclose_rat(&(x - &m));
            let at = jet.value.plus(&jet.slope.times(&d));
            at.sign_of().filter(|s| *s != 0)
        };
        self.cut_both(
            Rat::dyadic(&n - &Int::from(2), k as u64),
            Rat::dyadic(&n + &Int::from(3), k as u64),
            |root: &RealRoot<M>, x: &Rat| Some(mean_value(x).unwrap_or_else(|| root.cut_sign(x))),
        );
        self.sign_lo == 0 || self.width() <= *target
    }

    /// `⌊2^k·(m − q(m)/q′(m))⌋` at the dyadic `m = x`, from the model's
    /// double-word jet ([`SignModel::ball_jet_at`]) or multi-precision one
    /// ([`SignModel::big_jet_at`]) where its balls pin it down
    /// ([`step_floor`]), else from the exact jet: the same integer from
    /// every tier. `None` when `q′(m) = 0`.
    fn newton_floor(&mut self, x: f64, m: &Rat, k: i64) -> Option<Int> {
        // `2^k·m`, formed only where the `f64` pin does not decide.
        let scaled = || m.mul_pow2(k);
        if !self.balls_fail {
            if let Some(n) = self
                .base
                .ball_jet_at(m)
                .and_then(|jet| ball_step_floor(x, m, k, &jet))
            {
                return Some(n);
            }
            self.balls_fail = true;
        }
        let prec = u32::try_from(k + i64::from(NEWTON_BALL_MARGIN)).unwrap_or(u32::MAX);
        if let Some(n) = self
            .base
            .big_jet_at(m, prec)
            .and_then(|jet| step_floor(&scaled(), k, &jet))
        {
            return Some(n);
        }
        let jet = self.base.exact_jet_at(m);
        (!jet.slope.is_zero()).then(|| exact_step_floor(m, k, &jet))
    }

    /// Cuts at `a` and at `b` (each only if strictly inside and `sign`
    /// proves the sign of `p` there); whether that made the root exact or at
    /// least halved the enclosure.
    fn cut_both(
        &mut self,
        a: Rat,
        b: Rat,
        sign: impl Fn(&RealRoot<M>, &Rat) -> Option<i32>,
    ) -> bool {
        let old = self.width();
        for x in [a, b] {
            if x > self.lo && x < self.hi {
                if let Some(s) = sign(self, &x) {
                    self.cut(x, s);
                }
            }
        }
        self.sign_lo == 0 || self.width() * Rat::from(2) <= old
    }

    /// One exact Newton step, for when `f64` cannot resolve the root any
    /// further: from a short dyadic `m = a/2^j` in the middle half of the
    /// enclosure `I`, `x = m − p(m)/p′(m)` from the model's exact values
    /// `σ·p(m) = V·2^(−v)`, `σ·p′(m) = S·2^(−s)` ([`ExactJet`]), rounded
    /// down to `X/2^k` with `2^(−k)` about `max(w², target/4)` for the
    /// current width `w` (Newton's error is quadratic in `m`'s; one integer
    /// division, no gcd). The enclosure is then cut at `(X − 1)/2^k` and
    /// `(X + 2)/2^k`; `false` if the width did not halve.
    ///
    /// The sign of `p` at a cut `x` comes from the same two exact values:
    /// `p(x) = p(m) + p′(m)·D + p″(ξ)·D²/2` with `D = x − m` and `ξ ∈ I`
    /// (Taylor with Lagrange remainder). The linear part is one exact
    /// integer over a power of two, `V·2^(T−v) + S·d·2^(T−s−e)` for
    /// `D = d/2^e` and `T = max(v, s + e)`, and only the remainder is
    /// enclosed in `f64` (`p″` over `I`, times `D²`); where that does not
    /// decide, `p(x)` is evaluated exactly.
    ///
    /// The same step is first tried from the model's double-word jet, then
    /// from its multi-precision one at the step's grid plus
    /// [`NEWTON_BALL_MARGIN`] bits ([`RealRoot::ball_newton_jump`]); the
    /// exact jet is formed only when neither pins the step down.
    fn exact_newton_jump(&mut self, target: &Rat, w: &Rat) -> bool {
        let quarter = w * &Rat::from_frac(1, 4);
        let m = Rat::dyadic_in(&(&self.lo + &quarter), &(&self.hi - &quarter));
        let second = self.base.enclose_second(self.enclosure());
        if !self.balls_fail {
            if let Some(jet) = self.base.ball_jet_at(&m) {
                if let Some(done) = self.ball_newton_jump(target, w, &m, second, &jet) {
                    return done;
                }
                self.balls_fail = true;
            }
        }
        // The multi-precision tier: the step's grid `2^(−k)` (at most
        // [`newton_exponent`]'s bound without the model's reach, here from
        // bit lengths alone, within two bits) past the bits the value
        // `p(m) ≈ p′·(m − α)` cancels to, about the enclosure's, which
        // `δ = p(m)/p′(m)` is short of by as many.
        let wb = neg_log2(w);
        let k = step_grid(2 * wb, neg_log2(target), i64::MAX, wb) + 2;
        let prec = u32::try_from(k + i64::from(NEWTON_BALL_MARGIN)).unwrap_or(u32::MAX);
        if let Some(jet) = self.base.big_jet_at(&m, prec) {
            if let Some(done) = self.ball_newton_jump(target, w, &m, second, &jet) {
                return done;
            }
        }
        let jet = self.base.exact_jet_at(&m);
        if jet.slope.is_zero() {
            return false;
        }
        let (_, slope) = jet.enclose();
        let k = newton_exponent(w, target, slope, second);
        let x_scaled = exact_step_floor(&m, k, &jet);
        let (v, s) = (jet.value_exp, jet.slope_exp);
        let shl = |x: &Int, e: i64| x.shl(e as u64);
        let taylor_sign = |root: &RealRoot<M>, x: &Rat| {
            let d = x - &m;
            let e = d.dyadic_exponent().expect("dyadics differ by a dyadic") as i64;
            let t = v.max(s + e);
            let linear = shl(&jet.value, t - v) + shl(&(&jet.slope * d.numer()), t - s - e);
            let dd = Interval::from_rat(&d);
            let value =
                Interval::from_int_scaled(&linear, t) + second * dd.square() * Interval::point(0.5);
            Some(
                value
                    .sign()
                    .filter(|s| *s != 0)
                    .unwrap_or_else(|| root.cut_sign(x)),
            )
        };
        self.cut_both(
            Rat::dyadic(&x_scaled - &Int::one(), k as u64),
            Rat::dyadic(&x_scaled + &Int::from(2), k as u64),
            taylor_sign,
        )
    }

    /// The exact sign of `p` at a cut `x` next to the root (of
    /// [`RealRoot::past_float_jump`], or of an exact Newton step where its
    /// Taylor form did not decide): the model's double-word value of `p(x)`
    /// ([`SignModel::ball_sign_at`]) when its ball excludes zero, else
    /// [`SignModel::sign_at`]. The Taylor form's remainder comes from an
    /// enclosure of `p″` over the whole enclosure, often far wider than
    /// `p″` itself; the ball at `x` has no remainder, and costs a fraction
    /// of the exact evaluation.
    fn cut_sign(&self, x: &Rat) -> i32 {
        self.base
            .ball_sign_at(x)
            .unwrap_or_else(|| self.base.sign_at(x))
    }

    /// [`RealRoot::exact_newton_jump`] from a ball jet of the model
    /// (double-word, [`SignModel::ball_jet_at`], or multi-precision,
    /// [`SignModel::big_jet_at`]), when the balls pin down everything the
    /// exact jet would give: the slope is nonzero, its `f64` enclosure (the
    /// one the exact slope rounds to: every integer the ball allows has the
    /// same leading 64 bits), hence the same `k`, and `X` (both ends of the
    /// ball of `2^k·(m − q(m)/q′(m))` have the same floor). The cuts are
    /// then the exact step's, and each sign is proven by a ball or, where
    /// that does not decide, exactly: the very same step, without exact
    /// arithmetic on the closed form. `None` when anything is left open.
    fn ball_newton_jump<B: JetBall>(
        &mut self,
        target: &Rat,
        w: &Rat,
        m: &Rat,
        second: Interval,
        jet: &BallJet<B>,
    ) -> Option<bool> {
        jet.slope.sign_of().filter(|s| *s != 0)?;
        let slope = pinned(&jet.slope, jet.slope_exp)?;
        let k = newton_exponent(w, target, slope, second);
        // X = ⌊2^k·m − 2^k·δ⌋ with δ = σq(m)/σq′(m) in a ball.
        let x_scaled = step_floor(&m.mul_pow2(k), k, jet)?;
        let ball_sign = |root: &RealRoot<M>, x: &Rat| {
            let d = x - m;
            let linear = jet.value.plus(&jet.slope.times(&jet.value.enclose_rat(&d)));
            let dd = Interval::from_rat(&d);
            let remainder = second * dd.square() * Interval::point(0.5);
            Some(
                linear
                    .plus_interval(remainder)
                    .and_then(|b| b.sign_of())
                    .filter(|s| *s != 0)
                    .unwrap_or_else(|| root.cut_sign(x)),
            )
        };
        Some(self.cut_both(
            Rat::dyadic(&x_scaled - &Int::one(), k as u64),
            Rat::dyadic(&x_scaled + &Int::from(2), k as u64),
            ball_sign,
        ))
    }

    /// One round of [`RealRoot::sign_with`]'s Taylor tests from balls of
    /// `q(m)` and `q′(m)` (double-word or multi-precision,
    /// [`SignModel::ball_jet_at`], [`SignModel::big_jet_at`]) instead of
    /// exact values: [`BallRound::Sign`] when the symmetric form `q(m) +
    /// q′(m)·(I − m) ± sup|q″(I)|·r²/2` decides over the balls (then the
    /// exact form decides too, with the same sign: its linear part lies in
    /// the balls and its remainder is no larger), or when the balls pin
    /// down the `f64` enclosures of the exact values and the exact path's
    /// `f64` test on them decides; [`BallRound::Open`] when the balls prove
    /// that neither exact test would decide this round (and, where they
    /// can, whether the `f64` enclosure of `q(m)` holds zero); `None` when
    /// they cannot tell (the exact jet is needed).
    ///
    /// With `L = q(m) + q′(m)·(I − m)` over `I` (`m ∈ I`, so `I − m ∋ 0`),
    /// `ρ = sup|q″(I)|·r²/2` and `r = max|I − m|`, the exact Taylor test
    /// stays open iff `min L − ρ ≤ 0 ≤ max L + ρ`; the `f64` test encloses
    /// `L + [min(0, q″⁻), max(0, q″⁺)]·r²/2`, which holds zero (so stays
    /// open) when `min L + min(0, q″⁻)·r²/2 ≤ 0 ≤ max L + max(0, q″⁺)·r²/2`.
    fn ball_round<B: JetBall>(
        &self,
        m: &Rat,
        jet: &BallJet<B>,
        second: Interval,
    ) -> Option<BallRound> {
        let bound = second.lo.abs().max(second.hi.abs());
        if !bound.is_finite() {
            return None;
        }
        let (ol, oh) = self.offsets(m);
        let (dl, dh) = (jet.value.enclose_rat(&ol), jet.value.enclose_rat(&oh));
        let ((l_up, l_dn), (h_up, h_dn)) = (dl.abs_bounds(), dh.abs_bounds());
        let (r_up, r_dn) = (l_up.max(h_up), l_dn.max(h_dn));
        // r²/2 rounded up and down (three roundings), past f64's range:
        // values far below it come in multi-precision balls.
        let rem = Remainders::new(bound, r_up, r_dn, second, B::WIDE);
        let (l, h) = (
            jet.value.plus(&jet.slope.times(&dl)),
            jet.value.plus(&jet.slope.times(&dh)),
        );
        let at = |b: &B| {
            b.widened(rem.up)
                .and_then(|b| b.sign_of())
                .filter(|s| *s != 0)
        };
        if let (Some(sl), Some(sh)) = (at(&l), at(&h)) {
            if sl == sh {
                return Some(BallRound::Sign(sl));
            }
        }
        // Both exact tests open, proven from the balls' extremes: the
        // smaller upper end at most `x`, the larger lower end at least `y`.
        let open = |x: Scaled, y: Scaled| {
            (l.at_most(x) || h.at_most(x)) && (l.at_least(y) || h.at_least(y))
        };
        if !open(rem.down, rem.down.neg()) {
            return None;
        }
        // 2^(−960): far from where the exact value's f64 enclosure
        // underflows.
        let float_open = open(rem.minus_lo, rem.minus_hi);
        if float_open && jet.value.abs_at_least(2f64.powi(-960)) {
            return Some(BallRound::Open {
                value_zero: Some(false),
            });
        }
        // Otherwise the exact path's own f64 test, where the balls pin
        // down its operands.
        let pins = pinned(&jet.value, jet.value_exp).zip(pinned(&jet.slope, jet.slope_exp));
        match pins {
            Some((qm, dqm)) => {
                let test = float_taylor((&ol, &oh), qm, dqm, second);
                Some(match test.sign().filter(|s| *s != 0) {
                    Some(s) => BallRound::Sign(s),
                    None => BallRound::Open {
                        value_zero: Some(qm.contains_zero()),
                    },
                })
            }
            None => float_open.then_some(BallRound::Open { value_zero: None }),
        }
    }

    /// Shrinks the enclosure until `hi − lo <= max_width` (or the root turns
    /// out rational). Each step is proven by exact signs of `p`.
    ///
    /// At the end the simplest rational in the enclosure is tried: a root
    /// `a/b` with `b² < 1/(hi − lo)` is that rational, and is then reported
    /// exactly (one exact evaluation).
    pub fn refine_to(&mut self, max_width: &Rat) {
        self.narrow_to(max_width, u32::MAX);
        if self.sign_lo != 0 && self.may_hold_rational_root() {
            let s = Rat::simplest_in(&self.lo, &self.hi);
            if s != self.lo
                && s != self.hi
                && self.base.admits_root_at(&s)
                && self.base.sign_at(&s) == 0
            {
                self.lo = s.clone();
                self.hi = s;
                self.sign_lo = 0;
            }
        }
    }

    /// Whether the open enclosure may hold a rational root of the model:
    /// every one is `k/L` for an integer `k` and the model's
    /// [`SignModel::root_denominators`] `L`, so none is inside when no
    /// integer lies strictly between `lo·L` and `hi·L` (two products and
    /// floors, instead of the continued fraction of `Rat::simplest_in`).
    fn may_hold_rational_root(&self) -> bool {
        // L·w ≥ 2^(bits L − 1 + bits num w − 1 − bits den w) ≥ 2: then an
        // integer is strictly inside whatever the ends (the usual case when
        // L is long), with no product formed; a lower bound on bits L
        // ([`SignModel::root_denominator_bits`]) may show it without L.
        let w = self.width();
        let wide =
            |l_bits: u64| (l_bits + w.numer().bits()) as i64 - w.denom().bits() as i64 - 2 >= 1;
        if self.base.root_denominator_bits().is_some_and(wide) {
            return true;
        }
        let Some(l) = self.base.root_denominators() else {
            return true;
        };
        if wide(l.bits()) {
            return true;
        }
        let l = Rat::from_int(l);
        // The least integer above lo·L.
        let first = &(&self.lo * &l).floor() + &Int::one();
        Rat::from_int(first) < &self.hi * &l
    }

    /// Whether `gcd(p, q) = 1` is proven by the images of `p` and `q`
    /// modulo one word prime ([`SignModel::residues`],
    /// [`Residues::proves_coprime`](ccd_poly::Residues::proves_coprime)):
    /// then `q(α) ≠ 0`, with neither `q` nor the gcd over `ℤ[t]` formed.
    /// `false` means "not proven" (a common factor, `q ≡ 0`, or a prime
    /// dividing `lc(p)` or the resultant), and the exact gcd decides.
    fn coprime_by_images(&self, model: &impl SignModel) -> bool {
        let (p, kept) = self.base.residues();
        kept && p.proves_coprime(&model.residues().0)
    }

    /// [`RealRoot::refine_to`] without the final rational-root test: what
    /// [`RealRoot::sign_with`] needs between its rounds (the test's
    /// continued fraction costs time quadratic in the ends' bits, and the
    /// sign decisions do not need the root to be exact). It stops after
    /// `steps` steps (each at most one exact jet and three exact signs: a
    /// jump that did not halve the enclosure, its two cut signs and the
    /// bisection after it) even short of `max_width`, and tells whether it
    /// reached it.
    fn narrow_to(&mut self, max_width: &Rat, steps: u32) -> bool {
        // Float Newton until it reaches the root's float resolution; after
        // a failure farther out (outside its basin), a few bisections first.
        let mut float_newton = true;
        let mut float_wait = 0u32;
        // Bisections left before the next exact Newton attempt.
        let mut wait = 0u32;
        // Exact Newton once the enclosure is narrow enough for its
        // quadratic regime to be likely (`2^(−10)` of the span).
        let narrow = Rat::dyadic(Int::one(), 10);
        // Exact jumps that gain under 3 bits and leave the same end in
        // place, six in a row (three also caught passing slow stretches of
        // ordinary scenes, where the slivers cost up to 3 %): the root sits
        // next to that end with a close neighbour beyond it, where Newton's
        // step only halves the error (one bit per exact evaluation). A jump
        // that does not even halve the enclosure counts too, with the
        // bisection after it (near a cluster the step may fail every time,
        // and the bisections gain one bit each); once slivers were cut in
        // this call, two such jumps start them again.
        // Slivers `2^(−g)` of the width at that end are then cut off, `g`
        // doubling while the root is in them and halving while not (one
        // exact sign each): about `log₂` of the bits to the root's
        // neighbourhood instead of them. A sliver may overshoot
        // `max_width`: by at most the bits this call has gained, plus 16,
        // as `g` starts at 16 and doubles only after a sliver held the
        // root. (Whether `lo` stayed is told by its bit lengths: a cue
        // for speed only.)
        let lo_key = |r: &RealRoot<M>| (r.lo.numer().bits(), r.lo.denom().bits());
        let mut stuck = (None::<bool>, 0u32);
        let mut sliver: Option<(bool, u64)> = None;
        let mut slivered = false;
        // The width before the last exact jump, and `lo_key` then.
        let mut jumped: Option<(Rat, (u64, u64))> = None;
        for _ in 0..steps {
            let w = self.width();
            if self.sign_lo == 0 || w <= *max_width {
                return true;
            }
            if let Some((before, key)) = jumped.take() {
                let stayed = (w.mul_pow2(3) > before).then(|| lo_key(self) == key);
                stuck = match (stayed, stuck) {
                    (Some(end), (Some(last), n)) if end == last => (Some(end), n + 1),
                    (Some(end), _) => (Some(end), 1),
                    (None, _) => (None, 0),
                };
                match stuck {
                    (Some(from_lo), n) if n >= if slivered { 2 } else { 6 } => {
                        (sliver, stuck, slivered) = (Some((from_lo, 16)), (None, 0), true);
                    }
                    _ => {}
                }
            }
            if let Some((from_lo, g)) = sliver {
                sliver = if self.cut_sliver(from_lo, g, &w) {
                    Some((from_lo, g * 2))
                } else {
                    (g > 4).then_some((from_lo, g / 2))
                };
                continue;
            }
            let mut w = w;
            if float_newton && float_wait == 0 {
                match self.newton_jump(max_width) {
                    Jump::Progress => continue,
                    // The next jump would stop at the resolution: the
                    // exact steps follow at once.
                    Jump::Resolved => {
                        float_newton = false;
                        continue;
                    }
                    Jump::Failed => float_wait = 2,
                    Jump::AtResolution => float_newton = false,
                }
                // A jump that did not halve the enclosure may still have
                // moved an end.
                w = self.width();
            }
            float_wait = float_wait.saturating_sub(1);
            if wait == 0 && w <= narrow {
                let key = lo_key(self);
                let halved = self.exact_newton_jump(max_width, &w);
                jumped = Some((w, key));
                if halved {
                    continue;
                }
                // A failed jump counts towards `stuck` too.
                wait = 4;
            }
            wait = wait.saturating_sub(1);
            self.bisect();
        }
        self.sign_lo == 0 || self.width() <= *max_width
    }

    /// The sign of `q` over the enclosure `I` from the Taylor form at the
    /// dyadic `m ∈ I`: `q(x) = q(m) + q′(m)·(x − m) + q″(ξ)·(x − m)²/2`.
    /// The linear part is exact at both ends of `I` (it is monotone, so
    /// its extremes are there), and the remainder is bounded by
    /// `sup|q″(I)|·r²/2` with `r = max |x − m|`, the only rounded quantity
    /// (`second`, an outward enclosure: valid through underflow).
    fn exact_taylor_sign(&self, m: &Rat, jet: &ExactJet, second: Interval) -> Option<i32> {
        let bound = second.lo.abs().max(second.hi.abs());
        let bound = Rat::from_f64_exact(bound)?;
        let value = Rat::from_int(jet.value.clone()).mul_pow2(-jet.value_exp);
        let slope = Rat::from_int(jet.slope.clone()).mul_pow2(-jet.slope_exp);
        let (dl, dh) = (&self.lo - m, &self.hi - m);
        let (l, h) = (&value + &(&slope * &dl), &value + &(&slope * &dh));
        let r = dl.abs().max(dh.abs());
        let remainder = &(&bound * &(&r * &r)) * &Rat::from_frac(1, 2);
        let (low, high) = if l <= h { (l, h) } else { (h, l) };
        if (&low - &remainder).signum() > 0 {
            Some(1)
        } else if (&high + &remainder).signum() < 0 {
            Some(-1)
        } else {
            None
        }
    }

    fn enclosure(&self) -> Interval {
        Interval::from_rat(&self.lo).hull(&Interval::from_rat(&self.hi))
    }

    /// The offsets `lo − m` and `hi − m` of the enclosure's ends, exact.
    fn offsets(&self, m: &Rat) -> (Rat, Rat) {
        (&self.lo - m, &self.hi - m)
    }

    /// The exact sign (−1, 0, 1) of `q(α)`; see [`RealRoot::sign_with`],
    /// which this calls with a fresh [`SignProbe`].
    pub fn sign_of(&mut self, q: &ZPoly) -> i32 {
        self.sign_with(&SignProbe::new(q))
    }

    /// The exact sign (−1, 0, 1) of `q(α)` for a model of `q` (a
    /// [`SignProbe`] of an explicit polynomial, or any [`SignModel`]).
    ///
    /// Each round tries, on the isolating interval `I = [lo, hi]`:
    /// 1. the model's enclosure of `q` over `I` (cheap, but limited by
    ///    rounding when `q`'s coefficients dwarf `q(α)`);
    /// 2. the Taylor form with an EXACT centre and slope:
    ///    `q(I) ⊆ q(m) + q'(m)·(I − m) + q''(I)·(I − m)²/2`, with `q(m)` and
    ///    `q'(m)` computed exactly at a short dyadic `m ∈ I` and only `q''`
    ///    enclosed in floating point — its rounding is multiplied by the
    ///    squared width, so this decides any `q(α) ≠ 0` as soon as `I` is
    ///    narrower than about `|q(α)/q'(α)|`. It runs first with the
    ///    linear part in `f64` (cheap), then with it exact
    ///    (`RealRoot::exact_taylor_sign`: no underflow, however small
    ///    `q(α)` is beside `q`'s coefficients). Before either, the model's
    ///    double-word jet ([`SignModel::ball_jet_at`]), then its
    ///    multi-precision one ([`SignModel::big_jet_at`], for values out of
    ///    `f64`'s range or cancelling past 106 bits) is tried: each decides
    ///    only where the exact forms would, and proves when neither would,
    ///    so that the exact jet is formed only when no ball can tell
    ///    (`RealRoot::ball_round`; every step is the same as without them);
    /// 3. once `q(α) ≠ 0` is proven, at rounds 3, 6, 12, …, Descartes' rule
    ///    on `q`'s exact Bernstein coefficients over `I`. Where an exact
    ///    evaluation of `q` is costly ([`LOCAL_WORTH`](crate::LOCAL_WORTH)),
    ///    `q` re-centred next to `I` (an exact Taylor shift, then Horner's
    ///    scheme in multi-precision intervals) first: its enclosure over
    ///    `I`, and, when it proves a sign change between the ends (a root
    ///    of `q` in `I`, where the test cannot decide), the test skipped.
    ///
    /// Zero is decided exactly: `q(α) = 0` iff `g = gcd(p, q)` has a root in
    /// `I` (`q` from [`SignModel::exact`]; `q ≡ 0` gives `g = p`), and since
    /// `g | p` has at most the one root `α` there, that is a sign change of
    /// `g` between the ends. First, though, one image modulo a word prime
    /// usually proves `gcd(p, q) = 1` ([`SignModel::residues`]): then
    /// `q(α) ≠ 0` without forming `q` (same answer, same rounds). A
    /// first round on an enclosure at least `2^(−10)` wide tries 1 only
    /// (`WIDE_SIGN_LOG2`): the Taylor forms' remainder grows with the
    /// squared width. Between rounds the interval is refined (each
    /// step proven by exact signs of `p`): by 16 bits in the first rounds, then
    /// by twice as many each round, in at most 32 steps (`SIGN_NARROW_STEPS`)
    /// (a round after one cut short asks for the same bits again).
    /// docs/termination.md says why this ends.
    pub fn sign_with(&mut self, model: &impl SignModel) -> i32 {
        self.sign_within(model, None)
            .expect("an unbounded sign decides")
    }

    /// Whether `q(α) = 0`, decided as [`RealRoot::sign_with`] decides
    /// zero (one image modulo a word prime, else `gcd(p, q)`'s sign change
    /// over the enclosure), without the sign: where `q(α)` is tiny its
    /// sign may need a long narrowing, its zero test does not.
    pub fn vanishes_with(&self, model: &impl SignModel) -> bool {
        if self.sign_lo == 0 {
            return model.sign_at(&self.lo) == 0;
        }
        if self.coprime_by_images(model) {
            return false;
        }
        let g = self.base.exact().gcd(model.exact());
        g.degree().unwrap_or(0) >= 1 && g.sign_at(&self.lo) * g.sign_at(&self.hi) < 0
    }

    /// [`RealRoot::sign_with`] within a bound: `None` when a round ends
    /// undecided on an enclosure narrower than `2^−max_bits` (of the
    /// parameter), before it would narrow further (the bound is read
    /// between rounds, so the last round's narrowing may pass it). The
    /// narrowing done is kept; a later call starts its rounds over.
    pub fn sign_within(&mut self, model: &impl SignModel, max_bits: Option<i64>) -> Option<i32> {
        let mut state = SignState::default();
        // The rounds whose narrowing reached its width (all but those cut
        // short by `SIGN_NARROW_STEPS`): the gain doubles with these only.
        let mut reached = 0u32;
        for round in 0u32.. {
            if self.sign_lo == 0 {
                return Some(model.sign_at(&self.lo));
            }
            let whole = self.enclosure();
            if let Some(s) = decided(model.enclose(whole)) {
                return Some(s);
            }
            let width = self.width();
            // A wide enclosure is narrowed first (`WIDE_SIGN_LOG2`), as
            // the forms below failing on it would have it.
            let wide = round == 0 && width.mul_pow2(WIDE_SIGN_LOG2) >= Rat::one();
            if !wide {
                if let Some(s) = self.sign_forms(model, round, whole, &width, &mut state) {
                    return Some(s);
                }
            }
            // 16 bits a round while the floating-point forms may still
            // decide; then twice as many each round (exact Newton steps
            // double the bits anyway), so the rounds needed grow with the
            // logarithm of the bits that `q(α) ≠ 0` takes to show. A
            // narrowing cut short keeps the gain: its bits came slower.
            if max_bits.is_some_and(|bits| width.mul_pow2(bits) < Rat::one()) {
                return None;
            }
            let gain = 16i64 << reached.saturating_sub(EXACT_SIGN_ROUND - 1).min(40);
            let w = width.mul_pow2(-gain);
            if self.narrow_to(&w, SIGN_NARROW_STEPS) {
                reached += 1;
            }
        }
        unreachable!("the loop returns")
    }

    /// One round of [`RealRoot::sign_within`] past the enclosure of `q`
    /// over `I` (`whole`, `width` wide): the Taylor forms at a dyadic `m`
    /// in `I` (ball jets, then the exact jet), the zero test once, and
    /// Descartes' rule on schedule; the sign, or `None` for the round's
    /// narrowing.
    fn sign_forms(
        &self,
        model: &impl SignModel,
        round: u32,
        whole: Interval,
        width: &Rat,
        state: &mut SignState,
    ) -> Option<i32> {
        let m = Rat::dyadic_in(&self.lo, &self.hi);
        let second = model.enclose_second(whole);
        // The Taylor forms from double-word balls first: they decide
        // only where the exact forms below would, with the same sign,
        // and tell when those would not decide either.
        let ball = model
            .ball_jet_at(&m)
            .and_then(|jet| self.ball_round(&m, &jet, second))
            .or_else(|| {
                model
                    .big_jet_at(&m, SIGN_BALL_BITS)
                    .and_then(|jet| self.ball_round(&m, &jet, second))
            });
        let value_zero = match ball {
            Some(BallRound::Sign(s)) => return Some(s),
            Some(BallRound::Open {
                value_zero: Some(zero),
            }) => zero,
            // From round 1 on the zero test runs whatever q(m) is.
            Some(BallRound::Open { value_zero: None }) if round >= 1 => false,
            _ => {
                let jet = model.exact_jet_at(&m);
                let (qm, dqm) = jet.enclose();
                let (ol, oh) = self.offsets(&m);
                if let Some(s) = decided(float_taylor((&ol, &oh), qm, dqm, second)) {
                    return Some(s);
                }
                // The same Taylor form with its linear part kept exact:
                // no underflow however small `q(α)` is beside `q`'s
                // coefficients.
                if let Some(s) = self.exact_taylor_sign(&m, &jet, second) {
                    return Some(s);
                }
                qm.contains_zero()
            }
        };
        if !state.nonzero && (round >= 1 || value_zero) {
            if self.vanishes_with(model) {
                return Some(0);
            }
            state.nonzero = true;
        }
        // Once `q(α) ≠ 0` is proven, Descartes' rule on `q`'s exact
        // Bernstein coefficients over `I` decides as soon as `I` is free
        // of `q`'s roots. Its cost grows with the enclosure's bits, and
        // the exact Taylor form decides about as early whenever the
        // `f64` bound on `q″` is finite: so it runs at rounds 3, 6, 12, …
        // (and whenever that bound overflowed).
        let scheduled =
            round.is_multiple_of(EXACT_SIGN_ROUND) && (round / EXACT_SIGN_ROUND).is_power_of_two();
        if state.nonzero && (scheduled || !second.is_finite()) {
            // Where an exact evaluation of `q` is costly, `q`
            // re-centred next to `I` first, once per call
            // (`Local::near`; re-centring it whenever the width's bits
            // had doubled cost 0.2 s on two slow cases and gained on
            // none). Its enclosure over `I` decides about where the
            // test would (a sign it proves is the sign; it may decide
            // a round earlier, which leaves a wider enclosure than
            // before: a change of outputs, but not of any shipped
            // scene's, where it never runs), at a fraction of the cost.
            let q = model.exact();
            let mut skip = false;
            let cost = Cost::of(q);
            if cost.costly(&self.lo) {
                let local = state.near.get_or_insert_with(|| {
                    Local::near(q, &self.lo, &self.hi, neg_log2(width).max(0) as u64)
                });
                if let Some(l) = local {
                    let ladder = cost.sign_ladder(&self.lo);
                    if let Some(s) = l.sign_over(&self.lo, &self.hi, ladder.clone()) {
                        return Some(s);
                    }
                    // A root of q in I: the test cannot decide.
                    skip = l.changes_sign(&self.lo, &self.hi, ladder);
                }
            }
            if !skip {
                if let Some(s) = descartes_sign(q, &self.lo, &self.hi, width) {
                    return Some(s);
                }
            }
        }
        None
    }
}
