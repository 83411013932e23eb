//! Real roots on `[0, 1]` of an `f64` polynomial in Bernstein form, by de
//! Casteljau subdivision and Descartes' rule of signs on the Bernstein
//! coefficients (the paper's Section 5.3 method), lazily and in increasing
//! order.
//!
//! # Method
//! A depth-first, left-first walk over dyadic subintervals `[lo, hi]`, each
//! carrying the Bernstein coefficients of the polynomial on it. With `V` the
//! number of sign variations of a node's coefficients (zeros skipped), the
//! number of roots in the open interval is `V − 2k` (Proposition 3.1 through
//! the map `u ↦ (u − lo)/(hi − u)`), so
//!
//! * `V = 0`: no root, the node is dropped;
//! * `V = 1` with nonzero end coefficients: exactly one root, a sign change;
//!   it is refined by the Illinois variant of regula falsi (with bisection
//!   steps whenever an end value is zero or the bracket fails to halve in
//!   four steps) on the node's own coefficients, evaluated in `O(n)`;
//! * otherwise the node is split at its midpoint by de Casteljau's algorithm
//!   (the left half is visited first). A midpoint where the polynomial is
//!   exactly `0.0` is reported as a root itself.
//!
//! # Stopping rule (where floats guess)
//! * a simple root is refined until its bracket is at most [`ROOT_WIDTH`]
//!   wide in `u` (or no `f64` lies strictly inside it): the bracket is the
//!   candidate's `[lo, hi]`;
//! * a node still showing `V >= 2` once it is at most [`CLUSTER_WIDTH`]
//!   wide (or whose coefficients are all exactly `0.0`) is reported whole as
//!   ONE candidate of kind [`RootKind::Cluster`]: a multiple root, or roots
//!   closer than floats can separate. Adjacent clusters are merged;
//! * the end values at `u = 0` and `u = 1` are snapped to exactly zero when
//!   within `tol` of their magnitude (see [`crate::BernsteinF64`]), so a
//!   contact at an end of the span is found as a root exactly there.
//!
//! There is deliberately no noise floor for interior nodes: a polynomial
//! with many roots on `[0, 1]` has values far below its magnitude bound
//! there and still well-conditioned roots (the Bernstein basis is the
//! best-conditioned one on the interval); and since the walk subdivides one
//! fixed `f64` polynomial, it ends after at most about `n/2` clusters of
//! depth `log2(1/CLUSTER_WIDTH) = 40`, even where that polynomial is
//! rounding noise.
//!
//! Nothing is certified: rounding can flip the sign of a coefficient and so
//! add or remove a pair of roots (a double root — a grazing contact — seen
//! as two close roots or as none).
//!
//! # Cost
//! One split is `n(n + 1)/2` averages in place; the node coefficients live
//! in one stack buffer reused for the whole walk (no allocation per node
//! once the walk is as deep as it gets).

use ccd_poly::bernstein_f64::{binomial_row, eval_scaled};
use ccd_poly::BernsteinF64;

/// Width in `u` below which a node with `V >= 2` is reported as one
/// cluster candidate: `2^-40 ≈ 9.1e-13`.
pub const CLUSTER_WIDTH: f64 = 1.0 / (1u64 << 40) as f64;

/// Width in `u` to which a simple root's bracket is refined:
/// `2^-52 ≈ 2.2e-16` (about one ulp near `u = 1`).
pub const ROOT_WIDTH: f64 = f64::EPSILON;

/// Iteration cap of the regula falsi refinement (never reached in practice:
/// the bracket at least halves every four steps).
const MAX_REFINE_STEPS: usize = 400;

/// How a candidate root was found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RootKind {
    /// The polynomial is exactly `0.0` (after end snapping) at `lo == hi`.
    Point,
    /// A sign change isolated by `V = 1` and refined to its bracket.
    Simple,
    /// `[lo, hi]` may hold several roots or a multiple root (stopping rule).
    Cluster,
}

/// A candidate root: somewhere in `[lo, hi] ⊆ [0, 1]` (not certified).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Candidate {
    /// Lower end of the bracket.
    pub lo: f64,
    /// Upper end of the bracket.
    pub hi: f64,
    /// How it was found.
    pub kind: RootKind,
}

impl Candidate {
    /// The midpoint of the bracket: the float estimate of the root.
    pub fn estimate(&self) -> f64 {
        0.5 * (self.lo + self.hi)
    }
}

/// One entry of the walk's stack.
#[derive(Clone, Copy, Debug)]
enum Frame {
    /// A subinterval; its coefficients are the top `n + 1` of the buffer.
    Node { lo: f64, hi: f64 },
    /// A root exactly at a subdivision point or an end.
    Point(f64),
}

/// The roots of a polynomial on `[0, 1]`, lazily, in increasing order
/// (module docs). Later roots cost nothing until asked for, except that a
/// [`RootKind::Cluster`] is returned only once the next candidate (to merge
/// it if adjacent) has been found.
///
/// ```
/// use ccd_float::{BernsteinF64, Roots};
/// use ccd_arith::RingOps;
/// // (u − 0.25)(u − 0.7)(u − 2)
/// let p = BernsteinF64::from_power(&[-0.25, 1.0])
///     .times(&BernsteinF64::from_power(&[-0.7, 1.0]))
///     .times(&BernsteinF64::from_power(&[-2.0, 1.0]));
/// let roots: Vec<f64> = Roots::new(&p, 1e-13).map(|c| c.estimate()).collect();
/// assert_eq!(roots.len(), 2);
/// assert!((roots[0] - 0.25).abs() < 1e-15 && (roots[1] - 0.7).abs() < 1e-15);
/// ```
#[derive(Clone, Debug)]
pub struct Roots {
    /// The degree.
    n: usize,
    /// `C(n, i)`, for evaluating a node in `O(n)`.
    binom: Vec<f64>,
    /// Nodes and point roots still to visit (top = leftmost).
    stack: Vec<Frame>,
    /// The coefficients of the `Node` frames, `n + 1` each, in stack order.
    coeffs: Vec<f64>,
    /// The current node's coefficients.
    work: Vec<f64>,
    /// Scaled coefficients for evaluation during refinement.
    scaled: Vec<f64>,
    /// A candidate read ahead while merging clusters.
    lookahead: Option<Candidate>,
    /// Subdivisions performed so far.
    splits: usize,
}

/// `min(Var(b), 2)`, zeros skipped.
fn variations_capped(b: &[f64]) -> usize {
    let mut last = 0.0f64;
    let mut count = 0;
    for &c in b {
        if c != 0.0 {
            if last != 0.0 && (c > 0.0) != (last > 0.0) {
                count += 1;
                if count == 2 {
                    return 2;
                }
            }
            last = c;
        }
    }
    count
}

impl Roots {
    /// Starts the walk for `p` on `[0, 1]`; `tol` is the relative tolerance
    /// under which an end value counts as zero (module docs).
    pub fn new(p: &BernsteinF64, tol: f64) -> Roots {
        let mut b = p.coefficients();
        let m = p.magnitudes();
        let n = b.len() - 1;
        for i in [0, n] {
            if b[i].abs() <= tol * m[i] {
                b[i] = 0.0;
            }
        }
        let mut stack = Vec::with_capacity(64);
        if b[n] == 0.0 && n > 0 {
            stack.push(Frame::Point(1.0));
        }
        stack.push(Frame::Node { lo: 0.0, hi: 1.0 });
        if b[0] == 0.0 {
            stack.push(Frame::Point(0.0));
        }
        let mut coeffs = Vec::with_capacity(32 * (n + 1));
        coeffs.extend_from_slice(&b);
        Roots {
            n,
            binom: binomial_row(n),
            stack,
            coeffs,
            work: Vec::with_capacity(n + 1),
            scaled: Vec::with_capacity(n + 1),
            lookahead: None,
            splits: 0,
        }
    }

    /// de Casteljau subdivisions performed so far.
    pub fn splits(&self) -> usize {
        self.splits
    }

    /// The next candidate of the walk, before merging clusters.
    fn next_raw(&mut self) -> Option<Candidate> {
        let n = self.n;
        while let Some(frame) = self.stack.pop() {
            let (lo, hi) = match frame {
                Frame::Point(u) => {
                    return Some(Candidate {
                        lo: u,
                        hi: u,
                        kind: RootKind::Point,
                    })
                }
                Frame::Node { lo, hi } => (lo, hi),
            };
            let start = self.coeffs.len() - (n + 1);
            self.work.clear();
            self.work.extend_from_slice(&self.coeffs[start..]);
            self.coeffs.truncate(start);
            let cluster = Candidate {
                lo,
                hi,
                kind: RootKind::Cluster,
            };
            match variations_capped(&self.work) {
                0 if self.work.iter().all(|&c| c == 0.0) => return Some(cluster),
                0 => continue,
                1 if self.work[0] != 0.0 && self.work[n] != 0.0 => {
                    return Some(self.refine(lo, hi));
                }
                _ => {}
            }
            let mid = 0.5 * (lo + hi);
            if hi - lo <= CLUSTER_WIDTH || !(mid > lo && mid < hi) {
                return Some(cluster);
            }
            self.split(lo, mid, hi);
        }
        None
    }

    /// Splits the current node at `mid` and pushes right, the midpoint if
    /// it is a root, then left.
    fn split(&mut self, lo: f64, mid: f64, hi: f64) {
        let n = self.n;
        self.splits += 1;
        let base = self.coeffs.len();
        self.coeffs.resize(base + 2 * (n + 1), 0.0);
        let (right, left) = self.coeffs[base..].split_at_mut(n + 1);
        let b = &mut self.work[..];
        left[0] = b[0];
        for k in 1..=n {
            let row = &mut b[..=n - k + 1];
            for i in 0..row.len() - 1 {
                row[i] = 0.5 * (row[i] + row[i + 1]);
            }
            left[k] = row[0];
        }
        right.copy_from_slice(b);
        let at_mid = right[0];
        self.stack.push(Frame::Node { lo: mid, hi });
        if at_mid == 0.0 {
            self.stack.push(Frame::Point(mid));
        }
        self.stack.push(Frame::Node { lo, hi: mid });
    }

    /// The one root of the current node (`V = 1`, nonzero ends), by
    /// Illinois regula falsi on the node's local parameter.
    fn refine(&mut self, lo: f64, hi: f64) -> Candidate {
        let n = self.n;
        self.scaled.clear();
        self.scaled
            .extend(self.work.iter().zip(&self.binom).map(|(b, c)| b * c));
        let eval = |s: f64| eval_scaled(&self.scaled, s);
        let w = hi - lo;
        let (mut a, mut b) = (0.0f64, 1.0f64);
        let (mut fa, mut fb) = (self.work[0], self.work[n]);
        let sign_a = fa > 0.0;
        let mut kept = 0i32; // which end stayed last time: −1 left, +1 right
        let mut checkpoint = 1.0;
        for step in 1..=MAX_REFINE_STEPS {
            if (b - a) * w <= ROOT_WIDTH {
                break;
            }
            let stalled = step % 4 == 0 && b - a > 0.5 * checkpoint;
            if step % 4 == 0 {
                checkpoint = b - a;
            }
            let mid = 0.5 * (a + b);
            let mut c = if stalled || fa == 0.0 || fb == 0.0 {
                mid
            } else {
                (a * fb - b * fa) / (fb - fa)
            };
            if !(c > a && c < b) {
                c = mid;
                if !(c > a && c < b) {
                    break;
                }
            }
            let fc = eval(c);
            if fc == 0.0 {
                a = c;
                b = c;
                break;
            }
            if (fc > 0.0) == sign_a {
                a = c;
                fa = fc;
                if kept == 1 {
                    fb *= 0.5;
                }
                kept = 1;
            } else {
                b = c;
                fb = fc;
                if kept == -1 {
                    fa *= 0.5;
                }
                kept = -1;
            }
        }
        let (ulo, uhi) = (lo + a * w, lo + b * w);
        Candidate {
            lo: ulo.clamp(lo, hi),
            hi: uhi.clamp(lo, hi).max(ulo.clamp(lo, hi)),
            kind: RootKind::Simple,
        }
    }
}

impl Iterator for Roots {
    type Item = Candidate;

    fn next(&mut self) -> Option<Candidate> {
        let mut cur = self.lookahead.take().or_else(|| self.next_raw())?;
        if cur.kind != RootKind::Cluster {
            return Some(cur);
        }
        loop {
            match self.next_raw() {
                Some(c) if c.kind == RootKind::Cluster && c.lo <= cur.hi => cur.hi = c.hi,
                other => {
                    self.lookahead = other;
                    return Some(cur);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_arith::RingOps;

    /// `Π (u − r)`, each factor by its Bernstein coefficients `[−r, 1 − r]`.
    fn from_roots(roots: &[f64]) -> BernsteinF64 {
        roots.iter().fold(BernsteinF64::one(), |acc, r| {
            acc.times(&BernsteinF64::from_scaled(vec![-r, 1.0 - r]))
        })
    }

    #[test]
    fn simple_roots_in_order_to_full_precision() {
        let want = [0.05, 0.3, 1.0 / 3.0, 0.34, 0.77, 0.9999];
        let p = from_roots(&[want.as_slice(), &[-0.5, 1.5, 2.0]].concat());
        let got: Vec<Candidate> = Roots::new(&p, 1e-13).collect();
        assert_eq!(got.len(), want.len(), "{got:?}");
        for (c, w) in got.iter().zip(want) {
            assert!(c.lo <= c.hi && c.hi - c.lo <= 4.0 * ROOT_WIDTH, "{c:?}");
            assert!((c.estimate() - w).abs() < 1e-13, "{c:?} vs {w}");
        }
    }

    #[test]
    fn exact_zeros_at_ends_and_midpoints_are_points() {
        // u(1 − u): Bernstein coefficients [0, 1/2, 0], roots at both ends.
        let p = BernsteinF64::from_power(&[0.0, 1.0, -1.0]);
        let got: Vec<(f64, RootKind)> = Roots::new(&p, 1e-13).map(|c| (c.lo, c.kind)).collect();
        assert_eq!(got, [(0.0, RootKind::Point), (1.0, RootKind::Point)]);
        // (u − 1/2)²: [1/4, −1/4, 1/4], exactly 0 at the first split point.
        let p = from_roots(&[0.5, 0.5]);
        let got: Vec<(f64, RootKind)> = Roots::new(&p, 1e-13).map(|c| (c.lo, c.kind)).collect();
        assert_eq!(got, [(0.5, RootKind::Point)]);
    }

    #[test]
    fn a_double_root_off_the_dyadics_is_one_cluster_or_nothing() {
        // (u − 1/3)²: V stays 2 down to the cluster width, unless rounding
        // lifts the coefficients above zero first.
        let p = from_roots(&[1.0 / 3.0, 1.0 / 3.0]);
        let got: Vec<Candidate> = Roots::new(&p, 1e-13).collect();
        assert!(got.len() <= 1, "{got:?}");
        for c in &got {
            assert_eq!(c.kind, RootKind::Cluster);
            assert!((c.estimate() - 1.0 / 3.0).abs() < 1e-6, "{c:?}");
        }
    }

    #[test]
    fn lazy_first_root_does_not_walk_the_rest() {
        let roots: Vec<f64> = (1..=12).map(|k| k as f64 / 13.0).collect();
        let p = from_roots(&roots);
        let mut all = Roots::new(&p, 1e-13);
        let first = all.next().unwrap();
        let early = all.splits();
        assert!((first.estimate() - 1.0 / 13.0).abs() < 1e-12, "{first:?}");
        let rest: Vec<Candidate> = all.by_ref().collect();
        assert_eq!(rest.len(), 11);
        assert!(early * 3 < all.splits(), "{early} vs {}", all.splits());
    }

    #[test]
    fn degree_288_is_handled() {
        // 12 simple roots inside, 276 outside [0, 1] (as factors 1 − u/r,
        // of size about 1 on the span): degree 288.
        let inside: Vec<f64> = (0..12).map(|k| 0.03 + 0.08 * k as f64).collect();
        let p = (0..276).fold(from_roots(&inside), |acc, k| {
            let r = if k % 2 == 0 {
                -1.0 - k as f64 / 100.0
            } else {
                2.0 + k as f64 / 50.0
            };
            acc.times(&BernsteinF64::from_scaled(vec![1.0, 1.0 - 1.0 / r]))
        });
        assert_eq!(p.degree(), 288);
        let got: Vec<f64> = Roots::new(&p, 1e-13).map(|c| c.estimate()).collect();
        assert_eq!(got.len(), 12, "{got:?}");
        for (g, w) in got.iter().zip(&inside) {
            assert!((g - w).abs() < 1e-9, "{g} vs {w}");
        }
    }

    #[test]
    fn noise_is_one_cluster_not_an_explosion() {
        // (p + q)² − p² − 2pq − q² is rounding noise (flagged negligible
        // upstream); even if walked, it is a few candidates, not thousands.
        let p = from_roots(&[0.2, 0.4, 0.6, 0.8, 1.7]);
        let q = from_roots(&[0.21, 0.45, 0.6, 0.8, -1.7]);
        let s = p.plus(&q);
        let two_pq = p.times(&q).times(&BernsteinF64::from_i64(2));
        let noise = s
            .times(&s)
            .minus(&p.times(&p))
            .minus(&two_pq)
            .minus(&q.times(&q));
        assert!(noise.is_negligible(1e-12));
        let mut roots = Roots::new(&noise, 1e-10);
        let got: Vec<Candidate> = roots.by_ref().collect();
        assert!(
            got.len() <= 3 && roots.splits() < 100,
            "{got:?} {}",
            roots.splits()
        );
    }
}
