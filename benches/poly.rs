//! Benchmarks of the polynomial kernel (`ccd-poly`) at the sizes the
//! collision pipeline produces: degree-216 polynomials with 2000-bit
//! coefficients. Inputs are pseudo-random from a fixed xorshift seed.
//!
//! Run with `cargo bench -p ccd-benches --bench poly` (num-bigint kernel) and
//! `cargo bench -p ccd-benches --bench poly --features gmp`.

use ccd_arith::Int;
use ccd_poly::mul::{mul_kronecker, mul_multimodular};
use ccd_poly::ZPoly;
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::time::Duration;

/// Marsaglia's xorshift64: deterministic inputs without a `rand` dependency.
struct XorShift(u64);

impl XorShift {
    fn next(&mut self) -> u64 {
        let mut s = self.0;
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        self.0 = s;
        s
    }
    /// A random integer of exactly `bits` bits (top bit set), random sign.
    fn int(&mut self, bits: u64) -> Int {
        let n = bits.div_ceil(64) as usize;
        let mut limbs: Vec<u64> = (0..n).map(|_| self.next()).collect();
        let top = bits - 64 * (n as u64 - 1);
        if let Some(last) = limbs.last_mut() {
            *last = (*last >> (64 - top)) | (1 << (top - 1));
        }
        Int::from_u64_limbs(self.next() & 1 == 1, &limbs)
    }
    /// A polynomial of the given degree with `bits`-bit coefficients.
    fn poly(&mut self, degree: usize, bits: u64) -> ZPoly {
        ZPoly::new((0..=degree).map(|_| self.int(bits)).collect())
    }
}

fn config() -> Criterion {
    Criterion::default()
        .sample_size(20)
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3))
}

fn bench_poly(c: &mut Criterion) {
    let mut rng = XorShift(0x9E37_79B9_7F4A_7C15);
    let (a, b) = (rng.poly(216, 2000), rng.poly(216, 2000));
    let mut group = c.benchmark_group(format!("poly[{}]", ccd_arith::BACKEND));

    group.bench_function("mul_deg216_2000bit", |bch| bch.iter(|| black_box(&a * &b)));
    group.bench_function("mul_deg216_2000bit_kronecker", |bch| {
        bch.iter(|| black_box(mul_kronecker(a.coeffs(), b.coeffs())))
    });
    group.bench_function("mul_deg216_2000bit_multimodular", |bch| {
        bch.iter(|| black_box(mul_multimodular(a.coeffs(), b.coeffs())))
    });

    assert_eq!(a.gcd(&b), ZPoly::one(), "random inputs are coprime");
    group.bench_function("gcd_deg216_coprime", |bch| {
        bch.iter(|| black_box(a.gcd(&b)))
    });

    // g·u and g·v with deg g = 20, deg u = deg v = 196, 1000-bit factors:
    // degree 216 with about 2000-bit coefficients.
    let g = rng.poly(20, 1000);
    let (u, v) = (rng.poly(196, 1000), rng.poly(196, 1000));
    let (gu, gv) = (&g * &u, &g * &v);
    assert_eq!(
        gu.gcd(&gv),
        g.primitive_part(),
        "the common factor is the gcd"
    );
    group.bench_function("gcd_deg216_common_deg20", |bch| {
        bch.iter(|| black_box(gu.gcd(&gv)))
    });
    group.finish();
}

criterion_group! {
    name = benches;
    config = config();
    targets = bench_poly
}
criterion_main!(benches);
