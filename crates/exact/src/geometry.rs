//! Contact geometry on the exact path (`ccd-contact` does the math): the
//! certified point and normal at each contact, refining the contact's
//! enclosure when the box is too wide.

use ccd_arith::{Int, Interval, Rat};
use ccd_contact::{enclose, enclose_to_goal, from_quadrics, Case, ContactError, Goal};
use ccd_enclosure::BigInterval;
use ccd_motion::PlacedQuadric;
use ccd_scene::Scene;
use ccd_solver::{RealRoot, SignModel};
use ccd_subres::{closed_form, Quantity};
use ccd_timeline::{Box3, Geometry};

/// The exact path's stages, cheapest first: how far to narrow the
/// contact's enclosure first (a factor `2^−bits`) and the precisions then
/// tried for the closed forms (53: `f64` intervals), each stage followed
/// by [`Bodies::least_point`]. The exact rational evaluation at a rational
/// instant comes after the `f64` stages. The last three served extreme
/// radius ratios (`ratio-needle-k0064-*`: radii 1 and 10⁻⁶⁴), where the
/// closed forms cancel so heavily that `sr11` is separated from 0 only on
/// an enclosure of the instant some 10⁻¹⁶⁰ wide, at 2,048 bits; the least
/// point proves those contacts in `f64` now, and the stages remain for a
/// contact it cannot prove.
const STAGES: [(i64, &[u32]); 7] = [
    (0, &[53]),
    (20, &[53]),
    (64, &[128]),
    (64, &[256, 512]),
    (128, &[1024]),
    (256, &[2048]),
    (512, &[4096]),
];

/// What the exact path needs to compute the geometry of its contacts.
pub(crate) struct Bodies<'a> {
    scene: &'a Scene,
    pub(crate) a: PlacedQuadric,
    pub(crate) b: PlacedQuadric,
    goal: Goal,
}

impl<'a> Bodies<'a> {
    pub(crate) fn new(
        scene: &'a Scene,
        a: PlacedQuadric,
        b: PlacedQuadric,
        digits: u32,
    ) -> Bodies<'a> {
        Bodies {
            scene,
            a,
            b,
            goal: Goal::new(&scene.a, &scene.b, digits),
        }
    }

    /// `t0 + u·(t1 − t0)`.
    fn time(&self, u: &Rat) -> Rat {
        ccd_algorithm::time_on(&self.scene.span, u)
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

    /// The certified geometry at the rational instant `u` where the bodies
    /// touch (an end of a touch segment, or `t0`): the case of Theorem
    /// 3.10(2) from the exact sign of `sr11` at `u`, then the exact point
    /// ([`Bodies::at_rational`]), or, when `λ*` is not rational, the
    /// enclosures at the point instant `u` through the same precisions as
    /// [`Bodies::exact`], with [`Bodies::least_point`] after `f64`. A
    /// kernel of `λ*·A + B` that is exactly not one-dimensional is
    /// [`Geometry::NotASinglePoint`].
    pub(crate) fn at_touch(&self, u: &Rat) -> Geometry {
        let (qa, qb) = (self.a.quadric_at(u), self.b.quadric_at(u));
        let f = ccd_quadric::characteristic(&qa, &qb);
        let case = match closed_form(&f, Quantity::Sr11) {
            Some(s) if !s.is_zero() => Case::Simple,
            _ => Case::TwoDouble,
        };
        let rat = |m: [[Int; 4]; 4]| m.map(|row| row.map(Rat::from_int));
        match from_quadrics(&rat(qa), &rat(qb), case) {
            Ok(e) => {
                return Geometry::Point {
                    point: Box3::point(e.point),
                    normal: Box3::point(e.normal),
                    certified: true,
                }
            }
            Err(ContactError::Kernel) => return Geometry::NotASinglePoint,
            Err(_) => {}
        }
        let t = self.time(u);
        let (a, b, span) = (&self.scene.a, &self.scene.b, &self.scene.span);
        // The closed forms in f64, the least point, then the closed forms
        // at the other precisions.
        let fast = enclose_to_goal((a, b, span), (&t, &t), case, &self.goal, true, &[53]);
        if let Ok((g, true)) = fast {
            return g;
        }
        if let Some(g) = self.least_point(&t, &t) {
            return g;
        }
        let mut precisions: Vec<u32> = STAGES.iter().flat_map(|(_, p)| p.iter().copied()).collect();
        precisions.dedup();
        precisions.retain(|p| *p != 53);
        enclose((a, b, span), (&t, &t), case, &self.goal, true, &precisions)
            .or_else(|e| fast.map(|(g, _)| g).map_err(|_| e))
            .unwrap_or_else(ccd_contact::failed)
    }

    /// The contact as A's point where B's quadric is least, proven by
    /// Krawczyk's test in A's unit-sphere frame ([`ccd_contact::least_point`])
    /// for every time in `[lo, hi]`, in `f64` intervals, then 128 bits:
    /// `None` unless it meets the goal. It needs no case of Theorem 3.10(2)
    /// and no closed form, so it holds where those cancel (a needle or a
    /// disc of extreme radius ratio).
    fn least_point(&self, lo: &Rat, hi: &Rat) -> Option<Geometry> {
        // `t0 < t1` (a scene invariant), so lo <= hi.
        let bodies = (&self.scene.a, &self.scene.b, &self.scene.span);
        let fast = || ccd_contact::least_point::<Interval>(bodies, (lo, hi), 53).ok();
        let big = || ccd_contact::least_point::<BigInterval>(bodies, (lo, hi), 128).ok();
        let met = |g: &Geometry| self.goal.met(g);
        fast()
            .and_then(|e| e.to_geometry(true))
            .filter(met)
            .or_else(|| big().and_then(|e| e.to_geometry(true)).filter(met))
    }

    /// The certified geometry at the contact `root` (an isolated external
    /// touch) in the `case` of Theorem 3.10(2) that holds there (decided
    /// exactly by the caller: whether `sr11` vanishes at the root): interval
    /// evaluation of the closed forms at increasing precision, each stage
    /// followed by [`Bodies::least_point`], and, while
    /// the box is wider than the goal, a narrower enclosure of the instant
    /// (after the instant has been reported: the reported instant is
    /// unchanged).
    pub(crate) fn exact<M: SignModel + Clone>(&self, r: &mut RealRoot<M>, case: Case) -> Geometry {
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
            match enclose_to_goal((a, b, span), (&lo, &hi), case, goal, true, precisions) {
                Ok((g, true)) => return g,
                other => last = Some(other.map(|(g, _)| g)),
            }
            if let Some(g) = self.least_point(&lo, &hi) {
                return g;
            }
        }
        match last {
            // Certified, only wider than the goal.
            Some(Ok(g)) => g,
            Some(Err(e)) => ccd_contact::failed(e),
            None => Geometry::Unknown {
                reason: "no evaluation".into(),
            },
        }
    }
}
