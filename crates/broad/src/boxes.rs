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

/// An interval 3×3 matrix.
type Mat3 = [[Interval; 3]; 3];

/// How a body's points lie around its centre over one slice: `X = c + M·Y`
/// for some `|Y| <= 1` with `M` in the interval matrix (`M = R·diag(r)`),
/// or `|X − c| <= r` (a ball, for a body spinning in unknown ways).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Shape {
    /// `M` and `max r` (which bounds `‖M·Y‖` too).
    Matrix(Mat3, f64),
    Ball(f64),
}

/// The shapes of a body over the slices.
#[derive(Clone, Debug, PartialEq)]
enum Shapes {
    /// One shape throughout (a fixed orientation).
    Fixed(Shape),
    /// One per slice.
    PerSlice(Vec<Shape>),
    /// Not of the form `c + M·Y` (affine): boxes only.
    Unknown,
}

/// A body over the slices of the span: a certified box per slice (what
/// sweep-and-prune uses), and where available the centre box and the shape
/// around it, for the finer separating-plane test ([`Swept::apart`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Swept {
    /// Box `k` holds the body at every instant of slice `k`.
    pub boxes: Vec<Aabb>,
    /// The centre's box per slice (empty when the shapes are unknown).
    centres: Vec<[Interval; 3]>,
    shapes: Shapes,
}

impl Swept {
    /// The number of slices.
    pub fn slices(&self) -> usize {
        self.boxes.len()
    }

    /// `true` when bodies `self` and `o` are **proven** disjoint at every
    /// instant of slice `k`: their boxes are disjoint, or a plane separates
    /// them. The plane's normal `n` is the difference of the centre boxes'
    /// middles (any `n` is sound; this one usually works): with
    /// `h(n) = ‖Mᵀn‖` the body's support around its centre (`r·‖n‖` for a
    /// ball), every point `X` of `self` has `n·X <= n·c + h(n)` and every
    /// point `Y` of `o` has `n·Y >= n·c' − h'(n)`, so
    /// `n·(c' − c) > h(n) + h'(n)` over the slice's centre boxes (in
    /// outward-rounded intervals) puts the bodies strictly on the two sides
    /// of a plane. Bodies that touch share a point, so they are never
    /// `apart`.
    pub fn apart(&self, o: &Swept, k: usize) -> bool {
        if !self.boxes[k].overlaps(&o.boxes[k]) {
            return true;
        }
        match (
            self.centres.get(k),
            o.centres.get(k),
            self.shape(k),
            o.shape(k),
        ) {
            (Some(ca), Some(cb), Some(sa), Some(sb)) => plane(ca, &sa, cb, &sb),
            _ => false,
        }
    }

    /// `true` when a plane separates the bodies over the whole span (the
    /// test of [`Swept::apart`] on the hull of the centre boxes and the
    /// hull of the shapes): one test instead of one per slice.
    pub fn apart_throughout(&self, o: &Swept) -> bool {
        match (self.whole(), o.whole()) {
            (Some((ca, sa)), Some((cb, sb))) => plane(&ca, &sa, &cb, &sb),
            _ => false,
        }
    }

    /// The hull of the centre boxes and of the shapes over all slices.
    fn whole(&self) -> Option<([Interval; 3], Shape)> {
        let c = hull(self.centres.iter().copied());
        let s = match &self.shapes {
            Shapes::Fixed(s) => *s,
            Shapes::PerSlice(v) => v.iter().skip(1).fold(*v.first()?, |a, b| a.hull(b)),
            Shapes::Unknown => return None,
        };
        (!self.centres.is_empty()).then_some((c, s))
    }
}

impl Shape {
    /// A shape holding both.
    fn hull(&self, o: &Shape) -> Shape {
        match (self, o) {
            (Shape::Matrix(m, r), Shape::Matrix(n, s)) => Shape::Matrix(
                std::array::from_fn(|k| std::array::from_fn(|j| m[k][j].hull(&n[k][j]))),
                r.max(*s),
            ),
            (Shape::Matrix(_, r) | Shape::Ball(r), Shape::Matrix(_, s) | Shape::Ball(s)) => {
                Shape::Ball(r.max(*s))
            }
        }
    }
}

/// The separating-plane test of [`Swept::apart`] for centre boxes `ca`,
/// `cb` and shapes `sa`, `sb`.
fn plane(ca: &[Interval; 3], sa: &Shape, cb: &[Interval; 3], sb: &Shape) -> bool {
    {
        let n: [f64; 3] = std::array::from_fn(|i| cb[i].mid() - ca[i].mid());
        if !n.iter().all(|x| x.is_finite()) || n.iter().all(|&x| x == 0.0) {
            return false;
        }
        let n = n.map(Interval::point);
        let gap = (0..3)
            .map(|i| n[i] * (cb[i] - ca[i]))
            .fold(Interval::point(0.0), |s, x| s + x);
        let reach = Interval::point(support(sa, &n)) + Interval::point(support(sb, &n));
        gap.lo > reach.hi
    }
}

impl Swept {
    fn shape(&self, k: usize) -> Option<Shape> {
        match &self.shapes {
            Shapes::Fixed(s) => Some(*s),
            Shapes::PerSlice(v) => v.get(k).copied(),
            Shapes::Unknown => None,
        }
    }
}

/// An upper bound on `max_{|Y| <= 1} n·(M·Y) = ‖Mᵀn‖` (a ball: `r·‖n‖`).
fn support(s: &Shape, n: &[Interval; 3]) -> f64 {
    let norm = |v: [Interval; 3]| {
        sqrt_up(
            v.iter()
                .fold(Interval::point(0.0), |a, x| a + x.square())
                .hi,
        )
    };
    let ball = |r: f64| (r * norm(*n)).next_up();
    match s {
        Shape::Ball(r) => ball(*r),
        Shape::Matrix(m, r) => norm(std::array::from_fn(|j| {
            (0..3).fold(Interval::point(0.0), |a, k| a + m[k][j] * n[k])
        }))
        .min(ball(*r)),
    }
}

/// The shape `R·diag(r)` of a rotation in the interval matrix `rot` (a
/// ball of radius `max r` when the rotation is unknown).
fn shape(radii: &[Interval; 3], rot: Option<Mat3>) -> Shape {
    let rmax = radii.iter().map(|r| r.hi).fold(0.0, f64::max);
    match rot {
        Some(r) => Shape::Matrix(
            std::array::from_fn(|k| std::array::from_fn(|j| r[k][j] * radii[j])),
            rmax,
        ),
        None => Shape::Ball(rmax),
    }
}

/// The boxes (and centres and shapes) of `body` over the `2^depth` equal
/// slices `[t_k, t_{k+1}]`, `t_k = t0 + k·(t1 − t0)/2^depth`, of `span`
/// (`depth` is clamped to [`MAX_DEPTH`]): box `k` provably holds the body
/// at every `t` of slice `k`.
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
pub fn sweep(body: &Body, span: &[Rat; 2], depth: u32) -> Swept {
    let depth = depth.min(MAX_DEPTH);
    let slices = 1usize << depth;
    let radii = body.radii.each_ref().map(Interval::from_rat);
    // Centre boxes and shapes; `None` centres (a malformed curve) give
    // the whole space.
    let from = |centres: Vec<Option<[Interval; 3]>>, shapes: Shapes| {
        let boxes = centres
            .iter()
            .enumerate()
            .map(|(k, c)| match (c, &shapes) {
                (Some(c), Shapes::Fixed(s)) => place(*c, extent(s)),
                (Some(c), Shapes::PerSlice(v)) => place(*c, extent(&v[k])),
                _ => Aabb::ENTIRE,
            })
            .collect();
        let centres = centres
            .into_iter()
            .map(|c| c.unwrap_or([Interval::ENTIRE; 3]))
            .collect();
        Swept {
            boxes,
            centres,
            shapes,
        }
    };
    let fixed = |q: &Quat| Shapes::Fixed(shape(&radii, rotation(point_quat(q))));
    match &body.motion {
        Motion::Static {
            center,
            orientation,
        } => from(
            vec![Some(center.each_ref().map(Interval::from_rat)); slices],
            fixed(orientation),
        ),
        Motion::Translation {
            center,
            orientation,
        } => from(centre_boxes(center, depth), fixed(orientation)),
        Motion::Rigid {
            orientation,
            center,
        } => {
            let q = homogeneous::<_, 4, 5>(orientation, |q| q.each_ref().map(Interval::from_rat));
            // R(q) is unchanged by scaling q, so the numerator Σ Bᵢ·wᵢ·qᵢ
            // of a weighted curve gives the rotation too; the hull of its
            // control points bounds it.
            let shapes = leaves(&q, depth)
                .into_iter()
                .map(|q| {
                    let rot =
                        q.and_then(|q| rotation(hull(q.iter().map(|p| [p[0], p[1], p[2], p[3]]))));
                    shape(&radii, rot)
                })
                .collect();
            from(centre_boxes(center, depth), Shapes::PerSlice(shapes))
        }
        Motion::Affine { matrix } => {
            let h = homogeneous::<_, 12, 13>(matrix, |m| {
                std::array::from_fn(|i| Interval::from_rat(&m[i / 4][i % 4]))
            });
            let boxes = leaves(&h, depth)
                .into_iter()
                .map(|leaf| leaf.map_or(Aabb::ENTIRE, |leaf| affine_box(&leaf, &radii)))
                .collect();
            Swept {
                boxes,
                centres: Vec::new(),
                shapes: Shapes::Unknown,
            }
        }
        Motion::Helical {
            orientation,
            rate,
            center,
            ..
        } => {
            let shapes = if rate.is_zero() {
                fixed(orientation)
            } else {
                Shapes::Fixed(shape(&radii, None))
            };
            let centres = (0..slices)
                .map(|k| {
                    let t = Interval::from_rat(&crate::slice_start(span, depth, k))
                        .hull(&Interval::from_rat(&crate::slice_start(span, depth, k + 1)));
                    Some(helical_centre(center, t))
                })
                .collect();
            from(centres, shapes)
        }
    }
}

/// Upper bounds on the body's reach `‖row_k(M)‖` along each axis.
fn extent(s: &Shape) -> [f64; 3] {
    match s {
        Shape::Ball(r) => [*r; 3],
        Shape::Matrix(m, r) => m.map(|row| {
            sqrt_up(
                row.iter()
                    .fold(Interval::point(0.0), |a, x| a + x.square())
                    .hi,
            )
            .min(*r)
        }),
    }
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

/// `R(q) = M(q)/|q|²` (the contract's formula) for `q` in the box `q`,
/// each entry clamped to `[−1, 1]`; `None` when `|q|²` is not shown
/// positive on the box.
fn rotation([w, x, y, z]: [Interval; 4]) -> Option<Mat3> {
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
