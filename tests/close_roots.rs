//! Contacts as close as you like (issue 12, item 2): two and four contacts
//! within 10⁻¹⁰⁰, a tangency next to a crossing, a contact at `t0` or `t1`
//! next to an interior one — in the `sr0` branch (an ellipsoid pair of
//! different shapes) and the `sr11` branch (spheres, `sr0 ≡ 0`), the whole
//! scene turned by a rational quaternion.
//!
//! Truth by construction: A (semi-axes `ra`, top point at height 1 in its
//! frame) is static, and B (bottom point `1/2` below its centre) moves along
//! A's vertical axis with its centre at height `3/2 + g(u)`. Both bodies are
//! symmetric about that axis with horizontal tangent planes at those
//! points, so they are separate where `g > 0`, overlap where `g < 0` and
//! touch at one point where `g = 0`: the contact instants are the roots of
//! the polynomial `g`, chosen here, and a root of even multiplicity is a
//! tangential touch.

use ccd_arith::{Int, Rat};
use ccd_exact::{run_toml, Options, Outcome, State};
use ccd_stability::families::affine::{poly_from_roots, to_bernstein};

/// `10^(−k)`.
fn ten_to_minus(k: u32) -> Rat {
    Rat::new(Int::one(), Int::pow10(k)).expect("nonzero")
}

/// The power-basis coefficients of `Π (u − r_i)^(m_i)`, times `sign`.
fn from_roots(roots: &[(Rat, u32)], sign: i64) -> Vec<Rat> {
    let sign = Rat::from(sign);
    poly_from_roots(roots).iter().map(|c| c * &sign).collect()
}

/// Bernstein coefficients on `[0, 1]` of a power-basis polynomial.
fn bernstein(a: &[Rat]) -> Vec<Rat> {
    to_bernstein(a, a.len() - 1)
}

/// The rotation matrix of the quaternion `[w, x, y, z]` (not unit).
fn rotation(q: [i64; 4]) -> [[Rat; 3]; 3] {
    let [w, x, y, z] = q;
    let n = Rat::from(w * w + x * x + y * y + z * z);
    let m = [
        [
            w * w + x * x - y * y - z * z,
            2 * (x * y - w * z),
            2 * (x * z + w * y),
        ],
        [
            2 * (x * y + w * z),
            w * w - x * x + y * y - z * z,
            2 * (y * z - w * x),
        ],
        [
            2 * (x * z - w * y),
            2 * (y * z + w * x),
            w * w - x * x - y * y + z * z,
        ],
    ];
    m.map(|row| row.map(|v| &Rat::from(v) / &n))
}

fn text(r: &Rat) -> String {
    format!("\"{r}\"")
}

/// The scene of the module docs for the gap `g` (power basis in `u`), the
/// whole scene turned by `q`.
fn scene(ra: [&str; 3], rb: [&str; 3], g: &[Rat], q: [i64; 4]) -> String {
    let rot = rotation(q);
    let points: Vec<String> = bernstein(g)
        .iter()
        .map(|b| {
            let height = &Rat::from_frac(3, 2) + b;
            let p: Vec<String> = (0..3).map(|i| text(&(&rot[i][1] * &height))).collect();
            format!("[{}]", p.join(", "))
        })
        .collect();
    let quat = q.map(|v| v.to_string()).join(", ");
    format!(
        "[a]\nradii = [{}]\n[a.motion]\nkind = \"static\"\norientation = [{quat}]\n\
         [b]\nradii = [{}]\n[b.motion]\nkind = \"translation\"\norientation = [{quat}]\n\
         center = [{}]\n",
        ra.map(|r| format!("\"{r}\"")).join(", "),
        rb.map(|r| format!("\"{r}\"")).join(", "),
        points.join(", ")
    )
}

/// The two pairs: different shapes (`sr0` branch) and spheres (`sr11`).
const PAIRS: [([&str; 3], [&str; 3]); 2] = [
    (["2", "1", "3/2"], ["1", "1/2", "1/3"]),
    (["1", "1", "1"], ["1/2", "1/2", "1/2"]),
];

/// Turns: none, and a rational quaternion off every axis.
const TURNS: [[i64; 4]; 2] = [[1, 0, 0, 0], [2, 1, -1, 3]];

/// Runs every pair and turn for the gap `g` with roots `roots` (value,
/// multiplicity) and checks the contacts hold exactly those roots, in
/// order, and the states between them are the signs of `g`.
fn check(roots: &[(Rat, u32)], sign: i64, label: &str) {
    let g = from_roots(roots, sign);
    let eval = |u: &Rat| g.iter().rev().fold(Rat::zero(), |acc, c| &(&acc * u) + c);
    let options = Options {
        digits: 120,
        ..Options::default()
    };
    for (ra, rb) in PAIRS {
        for q in TURNS {
            let toml = scene(ra, rb, &g, q);
            let out: Outcome =
                run_toml(&toml, &options).unwrap_or_else(|e| panic!("{label}: {e}\n{toml}"));
            let case = format!("{label}, radii {ra:?}/{rb:?}, turn {q:?}");
            assert!(out.complete, "{case}: incomplete");
            assert_eq!(
                out.contacts.len(),
                roots.len(),
                "{case}: {:?}",
                out.contacts
            );
            for (c, (r, _)) in out.contacts.iter().zip(roots) {
                assert!(
                    c.lo <= *r && *r <= c.hi,
                    "{case}: {r} not in [{}, {}]",
                    c.lo,
                    c.hi
                );
                assert!(c.certified, "{case}");
            }
            for w in out.contacts.windows(2) {
                assert!(w[0].hi < w[1].lo, "{case}: enclosures not disjoint");
            }
            // Each open piece's state is the sign of g at a point inside it.
            for seg in out.timeline.iter().filter(|s| s.start.hi < s.end.lo) {
                let mid = Rat::midpoint(&seg.start.hi, &seg.end.lo);
                let want = match eval(&mid).signum() {
                    1 => State::Separate,
                    -1 => State::Overlap,
                    _ => State::Touch,
                };
                assert_eq!(seg.state, want, "{case}: at {mid}");
            }
        }
    }
}

fn third() -> Rat {
    Rat::from_frac(1, 3)
}

#[test]
fn two_crossings_within_1e_100() {
    let (a, d) = (third(), ten_to_minus(100));
    check(&[(a.clone(), 1), (&a + &d, 1)], 1, "two crossings");
}

#[test]
fn four_crossings_within_1e_100() {
    let (a, d) = (third(), ten_to_minus(100));
    let roots: Vec<(Rat, u32)> = (0..4).map(|i| (&a + &(&d * &Rat::from(i)), 1)).collect();
    check(&roots, 1, "four crossings");
}

#[test]
fn tangency_next_to_a_crossing() {
    let (a, d) = (third(), ten_to_minus(60));
    // g = −(u − a)²(u − a − δ): separate, touch at a, separate, overlap.
    check(
        &[(a.clone(), 2), (&a + &d, 1)],
        -1,
        "tangency then crossing",
    );
}

#[test]
fn contacts_at_the_span_ends_next_to_interior_ones() {
    let d = ten_to_minus(80);
    check(&[(Rat::zero(), 1), (d.clone(), 1)], 1, "at t0");
    let one = Rat::one();
    check(&[(&one - &d, 1), (one, 1)], 1, "at t1");
}
