//! Certified isolation of the roots of one quantity `q(t)` (`sr0`, or
//! `sr11` when `sr0 ≡ 0`) on a time interval by subdivision with interval
//! enclosures and the interval Newton operator, and refinement of a
//! certified root to a requested width.
//!
//! For a box `X` with midpoint `m`:
//! * the range of `q` over `X` is enclosed by the natural extension (the
//!   value part of a [`Dual`] evaluation over `X`) intersected with the
//!   mean-value form `q(m) + q'(X)·(X − m)` (`q'(X)` the derivative part);
//!   if it excludes 0, `X` holds no root;
//! * if `q'(X)` excludes 0, the interval Newton operator
//!   `N(X) = m − q(m)/q'(X)` holds every root in `X`: `N(X) ∩ X = ∅` proves
//!   there is none, and `N(X) ⊂ interior(X)` proves exactly one (a simple
//!   root), enclosed in `N(X)` (Moore 1966; Neumaier 1990, Thm. 5.1.7);
//! * otherwise `X` is bisected; a box narrower than the minimal width that
//!   still may hold a root without a proof (e.g. a tangential double root,
//!   where `q'` vanishes too) is kept as part of a **cluster**: an
//!   uncertified candidate, never dropped and never called certified.

use crate::dual::Dual;
use crate::placement::characteristic_at;
use crate::real::Real;
use crate::trig::Trig;
use ccd_arith::Rat;
use ccd_motion::Body;
use ccd_subres::{closed_form, Quantity};

/// One quantity of Theorem 3.10 as a function of t for a pair of bodies.
#[derive(Clone, Copy, Debug)]
pub struct Problem<'a> {
    /// First body.
    pub a: &'a Body,
    /// Second body.
    pub b: &'a Body,
    /// The span `[t0, t1]` (for the Bézier kinds' `u`).
    pub span: &'a [Rat; 2],
    /// The quantity whose roots are sought.
    pub target: Quantity,
}

impl Problem<'_> {
    /// The quantity enclosed at `t` (a point, a box, or a dual number).
    pub fn value<N: Trig>(&self, t: &N, prec: u32) -> N {
        // Only the products the target needs (Var has no closed form).
        closed_form(
            &characteristic_at(self.a, self.b, self.span, t, prec),
            self.target,
        )
        .unwrap_or_else(N::zero)
    }
}

/// What subdivision found in a box.
#[derive(Clone, Debug, PartialEq)]
pub enum Found<R> {
    /// Exactly one root, simple, proven by interval Newton; in this box.
    Root(R),
    /// Boxes that may hold roots but were not proven to hold exactly one
    /// (merged when adjacent): narrower than the minimal width, or with the
    /// value at the midpoint already indistinguishable from zero at this
    /// precision while the derivative may vanish (subdividing further at
    /// this precision cannot help).
    Cluster(R),
    /// Boxes left unexamined because [`Limits::max_boxes`] was reached
    /// (merged when adjacent): nothing is known about the roots in them.
    Undecided(R),
}

/// Limits of one subdivision.
#[derive(Clone, Copy, Debug)]
pub struct Limits {
    /// Boxes narrower than this are not bisected further.
    pub min_width: f64,
    /// Boxes examined at most; the rest become clusters.
    pub max_boxes: usize,
    /// Initial number of equal pieces.
    pub pieces: usize,
}

/// `n` equal pieces of `x` (ends shared exactly), in order.
fn pieces<R: Real>(x: &R, n: usize) -> Vec<R> {
    let mut out = vec![x.clone()];
    while out.len() < n {
        out = out
            .iter()
            .flat_map(|b| {
                let m = b.midpoint();
                [b.lower().hull(&m), m.hull(&b.upper())]
            })
            .collect();
    }
    out
}

/// A box with enclosures of the quantity at its two ends.
struct Task<R> {
    x: R,
    at_lo: R,
    at_hi: R,
}

/// The roots of `p.target` in `domain`, in increasing order, at the
/// precision of `domain`, and the number of boxes examined (at most
/// `limits.max_boxes`; every box beyond is returned as
/// [`Found::Undecided`], so the effort is bounded).
///
/// Besides the enclosure and Newton tests of the module documentation, a
/// box on which `q'` excludes zero (so `q` is strictly monotone) is settled
/// by the signs at its ends: equal proven signs mean no root, opposite ones
/// exactly one (intermediate value theorem), which is simple.
pub fn isolate<R: Real + Trig>(
    p: &Problem<'_>,
    domain: &R,
    limits: &Limits,
) -> (Vec<Found<R>>, usize) {
    let prec = domain.precision();
    let value = |t: &R| p.value(t, prec);
    let mut out: Vec<Found<R>> = Vec::new();
    let boxes = pieces(domain, limits.pieces.max(1));
    let mut ends: Vec<R> = boxes.iter().map(|b| value(&b.lower())).collect();
    ends.push(value(&domain.upper()));
    let mut stack: Vec<Task<R>> = boxes
        .into_iter()
        .enumerate()
        .map(|(i, x)| Task {
            x,
            at_lo: ends[i].clone(),
            at_hi: ends[i + 1].clone(),
        })
        .collect();
    stack.reverse();
    let mut examined = 0usize;
    let push_cluster = |out: &mut Vec<Found<R>>, x: R| {
        if let Some(Found::Cluster(c)) = out.last_mut() {
            if c.intersect(&x).is_some() {
                *c = c.hull(&x);
                return;
            }
        }
        out.push(Found::Cluster(x));
    };
    while let Some(Task { x, at_lo, at_hi }) = stack.pop() {
        if examined >= limits.max_boxes {
            if let Some(Found::Undecided(c)) = out.last_mut() {
                if c.intersect(&x).is_some() {
                    *c = c.hull(&x);
                    continue;
                }
            }
            out.push(Found::Undecided(x));
            continue;
        }
        examined += 1;
        let m = x.midpoint();
        // Second-order Taylor forms around m, with the point derivative
        // (tight) and the second derivative enclosed over X:
        // q(X) ⊆ q(m) + q'(m)·S + q''(X)·S²/2 and q'(X) ⊆ q'(m) + q''(X)·S,
        // with S = X − m. (A third-order form halves the number of boxes on
        // Example 5.2 but costs three times as much per box.)
        let at_m = p.value(&Dual::variable(m.clone()), prec);
        let (fm, d_m) = (at_m.v, at_m.d);
        let over = p.value(&Dual::variable(Dual::variable(x.clone())), prec);
        let (f_x, d_x, dd_x) = (over.v.v, over.v.d, over.d.d);
        let offset = x.minus(&m);
        let h = offset.abs_max();
        let half_sq = h.times(&h).hull(&R::zero()).div_small(2);
        let second_order = fm.plus(&d_m.times(&offset)).plus(&dd_x.times(&half_sq));
        let range = f_x.intersect(&second_order).unwrap_or(second_order);
        if !range.contains_zero() {
            continue;
        }
        let slope = d_m.plus(&dd_x.times(&offset));
        let derivative = d_x.intersect(&slope).unwrap_or(slope);
        let dual = Dual {
            v: range,
            d: derivative,
        };
        let width = x.width_f64();
        let monotone = dual.d.sign().is_some_and(|s| s != 0);
        if monotone {
            match (at_lo.sign(), at_hi.sign()) {
                (Some(a), Some(b)) if a != 0 && a == b => continue,
                (Some(a), Some(b)) if a != 0 && b != 0 => {
                    out.push(Found::Root(x));
                    continue;
                }
                _ => {}
            }
        }
        match fm.div(&dual.d) {
            Some(q) => {
                let newton = m.minus(&q);
                match newton.intersect(&x) {
                    None => continue,
                    Some(_) if newton.strictly_inside(&x) => {
                        out.push(Found::Root(newton));
                        continue;
                    }
                    _ => {}
                }
            }
            None if fm.contains_zero() => {
                push_cluster(&mut out, x);
                continue;
            }
            None => {}
        }
        let (left, right) = (x.lower().hull(&m), m.hull(&x.upper()));
        if width <= limits.min_width || left == x || right == x {
            push_cluster(&mut out, x);
            continue;
        }
        stack.push(Task {
            x: right,
            at_lo: fm.clone(),
            at_hi,
        });
        stack.push(Task {
            x: left,
            at_lo,
            at_hi: fm,
        });
    }
    (out, examined)
}

/// `hi − lo` exactly (`None` when unbounded).
pub fn width_rat<R: Real>(x: &R) -> Option<Rat> {
    Some(&x.hi_rat()? - &x.lo_rat()?)
}

/// Narrows a box known to hold exactly one simple root, until its width
/// is at most `target` or no step shrinks it: interval Newton steps (the
/// root lies in `N(X) ∩ X`), and bisection by the proven sign at the
/// midpoint when a Newton step gains less than half.
pub fn refine<R: Real + Trig>(p: &Problem<'_>, mut x: R, target: &Rat) -> R {
    let prec = x.precision();
    let mut sign_lo = p.value(&x.lower(), prec).sign();
    for _ in 0..400 {
        let Some(w) = width_rat(&x) else { return x };
        if &w <= target {
            return x;
        }
        let m = x.midpoint();
        let fm = p.value(&m, prec);
        let d = p.value(&Dual::variable(x.clone()), prec).d;
        if let Some(nx) = fm.div(&d).and_then(|q| m.minus(&q).intersect(&x)) {
            if width_rat(&nx).is_some_and(|nw| nw.mul_pow2(1) < w) {
                if nx.lower() != x.lower() {
                    sign_lo = p.value(&nx.lower(), prec).sign();
                }
                x = nx;
                continue;
            }
        }
        match (sign_lo, fm.sign()) {
            (Some(a), Some(b)) if a != 0 && b != 0 => {
                if a == b {
                    x = m.hull(&x.upper());
                    sign_lo = Some(b);
                } else {
                    x = x.lower().hull(&m);
                }
            }
            _ => return x,
        }
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_arith::Interval;
    use ccd_motion::{HelicalCenter, Motion};

    fn r(x: i64) -> Rat {
        Rat::from(x)
    }

    fn sphere_at(x: i64, radius: i64, vx: i64) -> Body {
        Body {
            radii: [r(radius), r(radius), r(radius)],
            motion: Motion::Helical {
                orientation: Motion::identity(),
                axis: [r(1), r(0), r(0)],
                rate: r(0),
                center: HelicalCenter {
                    base: [r(x), r(0), r(0)],
                    velocity: [r(vx), r(0), r(0)],
                    cos: [r(0), r(0), r(0)],
                    sin: [r(0), r(0), r(0)],
                    frequency: r(0),
                },
            },
        }
    }

    #[test]
    fn simple_roots_of_sr0_are_isolated_and_refined() {
        // An ellipsoid (2, 1, 1/2) passing a sphere: sr0 has simple roots at
        // the contacts.
        let mut a = sphere_at(-4, 1, 8);
        a.radii = [r(2), r(1), Rat::from_frac(1, 2)];
        let b = sphere_at(0, 1, 0);
        let span = [r(0), r(1)];
        let p = Problem {
            a: &a,
            b: &b,
            span: &span,
            target: Quantity::Sr0,
        };
        let (found, _) = isolate(
            &p,
            &Interval::new(-0.01, 1.01),
            &Limits {
                min_width: 1e-11,
                max_boxes: 100_000,
                pieces: 16,
            },
        );
        let roots: Vec<Interval> = found
            .iter()
            .filter_map(|f| match f {
                Found::Root(x) => Some(*x),
                Found::Cluster(_) | Found::Undecided(_) => None,
            })
            .collect();
        // Centres meet along x: touch when |x| = 3, i.e. t = 1/8 and 7/8.
        for t in [0.125, 0.875] {
            assert!(
                roots.iter().any(|x| x.lo <= t && t <= x.hi),
                "{t}: {found:?}"
            );
        }
        let x = roots
            .iter()
            .find(|x| x.lo <= 0.125 && 0.125 <= x.hi)
            .copied()
            .unwrap_or(Interval::ENTIRE);
        let fine = refine(&p, x, &Rat::from_frac(1, 1_000_000_000_000));
        assert!(
            fine.width() <= 1e-12 && fine.lo <= 0.125 && 0.125 <= fine.hi,
            "{fine:?}"
        );
    }
}
