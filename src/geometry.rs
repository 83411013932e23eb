//! Contact geometry on each path (`ccd-contact` does the math): the
//! certified point and normal at each exact contact, refining the contact's
//! enclosure when the box is too wide; float estimates; helical enclosures
//! where the case of Theorem 3.10(2) is proven, marked where not.

use crate::signs::Coefficients;
use crate::Options;
use ccd_arith::{Int, Rat};
use ccd_contact::{enclose, from_quadrics, Case, ContactError, Goal};
use ccd_motion::PlacedQuadric;
use ccd_scene::Scene;
use ccd_solver::{RealRoot, SignModel};
use ccd_subres::{closed_form, Quantity};
use ccd_timeline::{Box3, Geometry, Outcome};

/// The exact path's stages, cheapest first: how far to narrow the
/// contact's enclosure first (a factor `2^−bits`) and the precisions then
/// tried (53: `f64` intervals). The exact rational evaluation at a rational
/// instant comes after the `f64` stages.
const STAGES: [(i64, &[u32]); 4] = [(0, &[53]), (20, &[53]), (64, &[128]), (64, &[256, 512])];

/// What the exact path needs to compute the geometry of its contacts.
pub(crate) struct Bodies<'a> {
    scene: &'a Scene,
    a: &'a PlacedQuadric,
    b: &'a PlacedQuadric,
    goal: Goal,
}

fn failed(e: ContactError) -> Geometry {
    match e {
        ContactError::Kernel => Geometry::NotASinglePoint,
        other => Geometry::Unknown {
            reason: other.to_string(),
        },
    }
}

impl<'a> Bodies<'a> {
    pub(crate) fn new(
        scene: &'a Scene,
        a: &'a PlacedQuadric,
        b: &'a PlacedQuadric,
        opts: &Options,
    ) -> Bodies<'a> {
        Bodies {
            scene,
            a,
            b,
            goal: Goal::new(&scene.a, &scene.b, opts.digits),
        }
    }

    /// `t0 + u·(t1 − t0)`.
    fn time(&self, u: &Rat) -> Rat {
        let [t0, t1] = &self.scene.span;
        t0 + &(u * &(t1 - t0))
    }

    /// The point and normal exactly, at a rational contact instant `u`
    /// (case (2a): `λ*` and the kernel are rational), `None` when a square
    /// root is not rational.
    fn at_rational(&self, u: &Rat, case: Case) -> Option<Geometry> {
        let rat = |m: [[Int; 4]; 4]| m.map(|row| row.map(Rat::from_int));
        let (qa, qb) = (rat(self.a.quadric_at(u)), rat(self.b.quadric_at(u)));
        let e = from_quadrics(&qa, &qb, case).ok()?;
        Some(Geometry::Point {
            point: Box3::point(e.point),
            normal: Box3::point(e.normal),
            certified: true,
        })
    }

    /// The certified geometry at the contact `root` (an isolated external
    /// touch; `zeros` lists the quantities known to vanish there). The case
    /// of Theorem 3.10(2) is decided exactly (the sign of `sr11` at the
    /// root); then interval evaluation at increasing precision, and, while
    /// the box is wider than the goal, a narrower enclosure of the instant
    /// (after the instant has been reported: the reported instant is
    /// unchanged).
    pub(crate) fn exact<M: SignModel + Clone>(
        &self,
        r: &mut RealRoot<M>,
        coefficients: &Coefficients,
        zeros: &[Quantity],
    ) -> Geometry {
        let case = if zeros.contains(&Quantity::Sr11)
            || r.sign_with(&coefficients.model(Quantity::Sr11)) == 0
        {
            Case::TwoDouble
        } else {
            Case::Simple
        };
        let mut last = None;
        let mut tried_rational = false;
        for (k, (bits, precisions)) in STAGES.into_iter().enumerate() {
            if bits > 0 && r.lo() != r.hi() {
                let narrower = r.width().mul_pow2(-bits);
                r.refine_to(&narrower);
            }
            if k >= 2 && r.lo() == r.hi() && !tried_rational {
                tried_rational = true;
                if let Some(g) = self.at_rational(r.lo(), case) {
                    return g;
                }
            }
            let (lo, hi) = (self.time(r.lo()), self.time(r.hi()));
            let (a, b, span) = (&self.scene.a, &self.scene.b, &self.scene.span);
            let goal = &self.goal;
            match enclose((a, b, span), (&lo, &hi), case, goal, true, precisions) {
                Ok(g) if goal.met(&g) => return g,
                other => last = Some(other),
            }
        }
        match last {
            // Certified, only wider than the goal.
            Some(Ok(g)) => g,
            Some(Err(e)) => failed(e),
            None => Geometry::Unknown {
                reason: "no evaluation".into(),
            },
        }
    }
}

/// Float mode: an `f64` estimate at the midpoint of each contact (the
/// paper's setting, `certified: false`); the `sr0 ≡ 0` branch's contacts
/// are roots of `sr11`, case (2b).
pub(crate) fn estimates(scene: &Scene, outcome: &Outcome) -> Vec<Geometry> {
    let two_double = outcome.stats.branch.contains("sr11");
    outcome
        .contacts
        .iter()
        .map(|c| ccd_contact::estimate(&scene.a, &scene.b, &scene.span, &c.midpoint(), two_double))
        .collect()
}

/// Helical scenes: the contact's time enclosure as it stands (this path
/// does not refine it further), evaluated at increasing precision. Case
/// (2a) is proven when `sr11` excludes 0 on the enclosure, case (2b) when
/// the contacts are the roots of `sr11` with `sr0 ≡ 0` proven by
/// structure; otherwise, and for an uncertified instant, the boxes are
/// computed but marked `certified: false`.
pub(crate) fn helical(scene: &Scene, outcome: &Outcome, opts: &Options) -> Vec<Geometry> {
    let goal = Goal::new(&scene.a, &scene.b, opts.digits);
    let sr11_structural = outcome.stats.branch.contains("(structure), sr11");
    outcome
        .contacts
        .iter()
        .map(|c| {
            let t =
                ccd_arith::Interval::from_rat(&c.lo).hull(&ccd_arith::Interval::from_rat(&c.hi));
            let (_, qa, qb) =
                ccd_enclosure::centred_quadrics(&scene.a, &scene.b, &scene.span, &t, 53);
            let f = ccd_quadric::characteristic(&qa, &qb);
            let sr11_nonzero = closed_form(&f, Quantity::Sr11).is_some_and(|s| !s.contains_zero());
            let (case, proven) = if sr11_nonzero {
                (Case::Simple, true)
            } else {
                (Case::TwoDouble, sr11_structural)
            };
            let certified = c.certified && proven;
            let (a, b, span) = (&scene.a, &scene.b, &scene.span);
            let all = &ccd_contact::PRECISIONS;
            enclose((a, b, span), (&c.lo, &c.hi), case, &goal, certified, all)
                .unwrap_or_else(failed)
        })
        .collect()
}
