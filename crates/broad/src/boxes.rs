//! Certified boxes of one moving ellipsoid over the slices of the span.

use ccd_arith::{Interval, Rat};
use ccd_motion::{Bezier, Body, HelicalCenter, Motion, Quat};

use crate::MAX_DEPTH;

/// A closed axis-aligned box `lo <= x <= hi` (componentwise); bounds may be
/// infinite, never NaN.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// Lower corner.
    pub lo: [f64; 3],
    /// Upper corner.
    pub hi: [f64; 3],
}

impl Aabb {
    /// All of space: what a body gets whose numbers `f64` cannot bound.
    pub const ENTIRE: Aabb = Aabb {
        lo: [f64::NEG_INFINITY; 3],
        hi: [f64::INFINITY; 3],
    };

    /// The box `x[0] × x[1] × x[2]`.
    pub fn from_intervals(x: [Interval; 3]) -> Aabb {
        Aabb {
            lo: x.map(|i| i.lo),
            hi: x.map(|i| i.hi),
        }
    }

    /// The closed boxes share a point (touching faces count).
    pub fn overlaps(&self, o: &Aabb) -> bool {
        (0..3).all(|k| self.lo[k] <= o.hi[k] && o.lo[k] <= self.hi[k])
    }

    /// The smallest box holding both.
    pub fn hull(&self, o: &Aabb) -> Aabb {
        Aabb {
            lo: std::array::from_fn(|k| self.lo[k].min(o.lo[k])),
            hi: std::array::from_fn(|k| self.hi[k].max(o.hi[k])),
        }
    }

    /// The middle of the box along `axis` (for choosing a sweep axis; not
    /// certified, possibly infinite).
    pub fn mid(&self, axis: usize) -> f64 {
        0.5 * self.lo[axis] + 0.5 * self.hi[axis]
    }
}

/// A control point in homogeneous coordinates, `[w·P, w]`.
type Point<const K: usize> = [Interval; K];

/// The boxes of `body` over the `2^depth` equal slices `[t_k, t_{k+1}]`,
/// `t_k = t0 + k·(t1 − t0)/2^depth`, of `span` (`depth` is clamped to
/// [`MAX_DEPTH`]): box `k` provably holds the body at every `t` of slice
/// `k`.
///
/// Per motion kind, with `D = diag(r)` and `|Y| <= 1` the unit ball:
///
/// * `static`, `translation`, `rigid`: `X = R(t)·D·Y + c(t)`, so
///   `X_k ∈ c_k ± ‖row_k(R)·D‖`. The centre `c` over a slice lies in the
///   hull of the slice's control points (de Casteljau halvings of
///   `[wᵢcᵢ, wᵢ]`, weights positive). `R` is the fixed `R(q)` for the
///   first two; for `rigid`, `R(q)` evaluated in interval arithmetic on the
///   box of the quaternion curve's slice control points (the curve lies in
///   their hull) and clamped to `[−1, 1]`, and `‖row_k(R)·D‖ <= max r`
///   always.
/// * `affine`: per slice control matrix `[Lᵢ | dᵢ]`,
///   `X_k ∈ [minᵢ(d_ik − ‖row_k(Lᵢ)·D‖), maxᵢ(d_ik + ‖row_k(Lᵢ)·D‖)]`
///   (for fixed `Y`, `X(t)` is a positive-weight rational Bézier curve
///   with control points `Lᵢ·D·Y + dᵢ`).
/// * `helical`: `c(t) = base + velocity·t + cos·cos(ft) + sin·sin(ft)` with
///   `t` in the slice as an interval and `|cos_k·cos θ + sin_k·sin θ| <=
///   √(cos_k² + sin_k²)` (exactly `cos_k` when `f = 0`); extent `max r`
///   while it spins (`rate ≠ 0`), `‖row_k(R)·D‖` otherwise.
///
/// All in outward-rounded interval arithmetic: a box is never smaller
/// than the exact set. A body built in code with an empty curve or
/// mismatched weights, or numbers beyond `f64`, gets [`Aabb::ENTIRE`].
pub fn sweep(body: &Body, span: &[Rat; 2], depth: u32) -> Vec<Aabb> {
    let depth = depth.min(MAX_DEPTH);
    let slices = 1usize << depth;
    let radii = body.radii.each_ref().map(Interval::from_rat);
    let boxes = match &body.motion {
        Motion::Static {
            center,
            orientation,
        } => {
            let c = center.each_ref().map(Interval::from_rat);
            vec![place(c, extent(&radii, rotation(point_quat(orientation)))); slices]
        }
        Motion::Translation {
            center,
            orientation,
        } => {
            let e = extent(&radii, rotation(point_quat(orientation)));
            centre_boxes(center, depth)
                .into_iter()
                .map(|c| c.map_or(Aabb::ENTIRE, |c| place(c, e)))
                .collect()
        }
        Motion::Rigid {
            orientation,
            center,
        } => {
            let q = homogeneous::<_, 4, 5>(orientation, |q| q.each_ref().map(Interval::from_rat));
            let q = leaves(&q, depth);
            centre_boxes(center, depth)
                .into_iter()
                .zip(q)
                .map(|(c, q)| match (c, q) {
                    (Some(c), Some(q)) => {
                        // R(q) is unchanged by scaling q, so the numerator
                        // Σ Bᵢ·wᵢ·qᵢ of a weighted curve gives the rotation
                        // too; the hull of its control points bounds it.
                        let qbox = hull(q.iter().map(|p| [p[0], p[1], p[2], p[3]]));
                        place(c, extent(&radii, rotation(qbox)))
                    }
                    _ => Aabb::ENTIRE,
                })
                .collect()
        }
        Motion::Affine { matrix } => {
            let h = homogeneous::<_, 12, 13>(matrix, |m| {
                std::array::from_fn(|i| Interval::from_rat(&m[i / 4][i % 4]))
            });
            leaves(&h, depth)
                .into_iter()
                .map(|leaf| leaf.map_or(Aabb::ENTIRE, |leaf| affine_box(&leaf, &radii)))
                .collect()
        }
        Motion::Helical {
            orientation,
            rate,
            center,
            ..
        } => {
            let e = if rate.is_zero() {
                extent(&radii, rotation(point_quat(orientation)))
            } else {
                extent(&radii, None)
            };
            (0..slices)
                .map(|k| {
                    let t = Interval::from_rat(&crate::slice_start(span, depth, k))
                        .hull(&Interval::from_rat(&crate::slice_start(span, depth, k + 1)));
                    place(helical_centre(center, t), e)
                })
                .collect()
        }
    };
    debug_assert_eq!(boxes.len(), slices);
    boxes
}

/// `c ± e`, outward rounded.
fn place(c: [Interval; 3], e: [f64; 3]) -> Aabb {
    Aabb::from_intervals(std::array::from_fn(|k| c[k] + Interval::new(-e[k], e[k])))
}

/// An upper bound on `√x` (`f64::sqrt` is correctly rounded).
fn sqrt_up(x: f64) -> f64 {
    if x <= 0.0 {
        0.0
    } else {
        x.sqrt().next_up()
    }
}

/// Upper bounds on `‖row_k(R)·diag(r)‖`, `k = 0, 1, 2`, for a rotation in
/// the interval matrix `rot` (any rotation when `None`): at most `max r`.
fn extent(radii: &[Interval; 3], rot: Option<[[Interval; 3]; 3]>) -> [f64; 3] {
    let rmax = radii.iter().map(|r| r.hi).fold(0.0, f64::max);
    let Some(rot) = rot else { return [rmax; 3] };
    rot.map(|row| {
        let s = (0..3)
            .map(|j| row[j].square() * radii[j].square())
            .fold(Interval::point(0.0), |a, b| a + b);
        sqrt_up(s.hi).min(rmax)
    })
}

/// `R(q) = M(q)/|q|²` (the contract's formula) for `q` in the box `q`,
/// each entry clamped to `[−1, 1]`; `None` when `|q|²` is not shown
/// positive on the box.
fn rotation([w, x, y, z]: [Interval; 4]) -> Option<[[Interval; 3]; 3]> {
    let n = w.square() + x.square() + y.square() + z.square();
    if n.lo.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        return None;
    }
    let two = Interval::point(2.0);
    let m = [
        [
            w.square() + x.square() - y.square() - z.square(),
            two * (x * y - w * z),
            two * (x * z + w * y),
        ],
        [
            two * (x * y + w * z),
            w.square() - x.square() + y.square() - z.square(),
            two * (y * z - w * x),
        ],
        [
            two * (x * z - w * y),
            two * (y * z + w * x),
            w.square() - x.square() - y.square() + z.square(),
        ],
    ];
    Some(m.map(|row| {
        row.map(|e| {
            let e = e.div_positive(n);
            Interval {
                lo: e.lo.max(-1.0),
                hi: e.hi.min(1.0),
            }
        })
    }))
}

/// A fixed quaternion as point intervals (or enclosures of its entries).
fn point_quat(q: &Quat) -> [Interval; 4] {
    q.each_ref().map(Interval::from_rat)
}

/// The control points of a Bézier curve as homogeneous intervals
/// `[wᵢ·Pᵢ, wᵢ]` (`wᵢ = 1` without weights); `None` for a malformed curve
/// (no point, or not one weight per point).
fn homogeneous<P, const N: usize, const K: usize>(
    c: &Bezier<P>,
    coords: impl Fn(&P) -> [Interval; N],
) -> Option<Vec<Point<K>>> {
    debug_assert_eq!(K, N + 1);
    if c.points.is_empty()
        || c.weights
            .as_ref()
            .is_some_and(|w| w.len() != c.points.len())
    {
        return None;
    }
    Some(
        c.points
            .iter()
            .enumerate()
            .map(|(i, p)| {
                let w = c
                    .weights
                    .as_ref()
                    .map_or(Interval::point(1.0), |w| Interval::from_rat(&w[i]));
                let p = coords(p);
                std::array::from_fn(|k| if k < N { p[k] * w } else { w })
            })
            .collect(),
    )
}

/// de Casteljau at `u = 1/2`: the control points of the two halves.
fn halve<const K: usize>(c: &[Point<K>]) -> (Vec<Point<K>>, Vec<Point<K>>) {
    let n = c.len();
    let mut work = c.to_vec();
    let mut left = Vec::with_capacity(n);
    let mut right = vec![work[n - 1]; n];
    left.push(work[0]);
    for level in 1..n {
        for i in 0..n - level {
            work[i] = std::array::from_fn(|k| work[i][k].average(work[i + 1][k]));
        }
        left.push(work[0]);
        right[n - 1 - level] = work[n - 1 - level];
    }
    (left, right)
}

/// The control points of each of the `2^depth` slices, in order (`None`
/// throughout for a malformed curve).
fn leaves<const K: usize>(c: &Option<Vec<Point<K>>>, depth: u32) -> Vec<Option<Vec<Point<K>>>> {
    let Some(c) = c else {
        return vec![None; 1 << depth];
    };
    if depth == 0 || c.len() == 1 {
        return vec![Some(c.clone()); 1 << depth];
    }
    let (l, r) = halve(c);
    let mut out = leaves(&Some(l), depth - 1);
    out.extend(leaves(&Some(r), depth - 1));
    out
}

/// `[w·P, w] → P` when `w` is shown positive, else the whole line.
fn dehomogenise<const K: usize, const N: usize>(h: &Point<K>) -> [Interval; N] {
    let w = h[K - 1];
    std::array::from_fn(|k| {
        if w.lo > 0.0 {
            h[k].div_positive(w)
        } else {
            Interval::ENTIRE
        }
    })
}

/// The interval hull of points.
fn hull<const N: usize>(mut points: impl Iterator<Item = [Interval; N]>) -> [Interval; N] {
    let first = points.next().unwrap_or([Interval::ENTIRE; N]);
    points.fold(first, |a, p| std::array::from_fn(|k| a[k].hull(&p[k])))
}

/// The box of the centre curve over each slice: the hull of the slice's
/// control points (`None` for a malformed curve).
fn centre_boxes(c: &Bezier<[Rat; 3]>, depth: u32) -> Vec<Option<[Interval; 3]>> {
    let h = homogeneous::<_, 3, 4>(c, |p| p.each_ref().map(Interval::from_rat));
    leaves(&h, depth)
        .into_iter()
        .map(|leaf| leaf.map(|pts| hull(pts.iter().map(dehomogenise::<4, 3>))))
        .collect()
}

/// The box of an affine body over one slice from its control matrices
/// `[wᵢLᵢ, wᵢdᵢ, wᵢ]` (entries `L_kj` at `4k + j`, `d_k` at `4k + 3`).
fn affine_box(leaf: &[Point<13>], radii: &[Interval; 3]) -> Aabb {
    let per_point = leaf.iter().map(|h| {
        let m: [Interval; 12] = dehomogenise(h);
        std::array::from_fn(|k| {
            let s = (0..3)
                .map(|j| m[4 * k + j].square() * radii[j].square())
                .fold(Interval::point(0.0), |a, b| a + b);
            let e = sqrt_up(s.hi);
            m[4 * k + 3] + Interval::new(-e, e)
        })
    });
    Aabb::from_intervals(hull(per_point))
}

/// The helical centre for `t` in the interval `t`.
fn helical_centre(c: &HelicalCenter, t: Interval) -> [Interval; 3] {
    let f = |x: &Rat| Interval::from_rat(x);
    std::array::from_fn(|k| {
        let wave = if c.frequency.is_zero() {
            f(&c.cos[k])
        } else {
            let a = sqrt_up((f(&c.cos[k]).square() + f(&c.sin[k]).square()).hi);
            Interval::new(-a, a)
        };
        f(&c.base[k]) + f(&c.velocity[k]) * t + wave
    })
}
