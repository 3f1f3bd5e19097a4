//! Gauss–Legendre quadrature, used to compute the Fourier transform of the NUFFT kernel.

use std::f64::consts::PI;

/// Nodes and weights of the q-point Gauss–Legendre rule on [−1, 1]:
/// ∫_{−1}^{1} f(z) dz ≈ Σ_i w_i f(z_i), exact for polynomials of degree ≤ 2q − 1.
///
/// The nodes are the roots of the Legendre polynomial P_q, found by Newton's method from
/// the initial guess cos(π(i + 3/4)/(q + 1/2)); P_q and P_{q−1} come from the three-term
/// recurrence (j+1) P_{j+1} = (2j+1) z P_j − j P_{j−1}, the derivative from
/// P_q'(z) = q (z P_q − P_{q−1}) / (z² − 1), and the weights are w_i = 2 / ((1 − z_i²) P_q'(z_i)²)
/// (Abramowitz & Stegun 25.4.29). Nodes are returned in increasing order, symmetric about 0.
/// `q = 0` gives empty vectors.
pub fn gauss_legendre(q: usize) -> (Vec<f64>, Vec<f64>) {
    let mut nodes = vec![0.0; q];
    let mut weights = vec![0.0; q];
    let qf = q as f64;
    // Legendre P_q and its derivative at z.
    let eval = |z: f64| -> (f64, f64) {
        let (mut p_prev, mut p) = (1.0, z);
        if q == 0 {
            return (1.0, 0.0);
        }
        for j in 1..q {
            let jf = j as f64;
            let next = ((2.0 * jf + 1.0) * z * p - jf * p_prev) / (jf + 1.0);
            p_prev = p;
            p = next;
        }
        (p, qf * (z * p - p_prev) / (z * z - 1.0))
    };
    for i in 0..q.div_ceil(2) {
        let mut z = (PI * (i as f64 + 0.75) / (qf + 0.5)).cos();
        for _ in 0..100 {
            let (p, dp) = eval(z);
            let dz = p / dp;
            z -= dz;
            if dz.abs() <= 1e-16 * z.abs().max(1.0) {
                break;
            }
        }
        let (_, dp) = eval(z);
        let w = 2.0 / ((1.0 - z * z) * dp * dp);
        // Root i (from the right) and its mirror image.
        nodes[q - 1 - i] = z;
        nodes[i] = -z;
        weights[q - 1 - i] = w;
        weights[i] = w;
    }
    if q % 2 == 1 {
        // The middle root is exactly 0 for odd q.
        nodes[q / 2] = 0.0;
        let (_, dp) = eval(0.0);
        weights[q / 2] = 2.0 / (dp * dp);
    }
    (nodes, weights)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn five_point_rule_matches_closed_form() {
        // A&S 25.4.29 / closed form: nodes 0, ±(1/3)√(5 − 2√(10/7)), ±(1/3)√(5 + 2√(10/7));
        // weights 128/225, (322 + 13√70)/900, (322 − 13√70)/900.
        let (z, w) = gauss_legendre(5);
        let a = (5.0 - 2.0 * (10.0f64 / 7.0).sqrt()).sqrt() / 3.0;
        let b = (5.0 + 2.0 * (10.0f64 / 7.0).sqrt()).sqrt() / 3.0;
        let s70 = 70.0f64.sqrt();
        let expect_z = [-b, -a, 0.0, a, b];
        let expect_w = [
            (322.0 - 13.0 * s70) / 900.0,
            (322.0 + 13.0 * s70) / 900.0,
            128.0 / 225.0,
            (322.0 + 13.0 * s70) / 900.0,
            (322.0 - 13.0 * s70) / 900.0,
        ];
        for i in 0..5 {
            assert!((z[i] - expect_z[i]).abs() < 1e-15, "node {i}");
            assert!((w[i] - expect_w[i]).abs() < 1e-15, "weight {i}");
        }
    }

    #[test]
    fn integrates_polynomials_exactly_up_to_degree_2q_minus_1() {
        for q in [1usize, 2, 7, 16, 40] {
            let (z, w) = gauss_legendre(q);
            assert!((w.iter().sum::<f64>() - 2.0).abs() < 1e-13, "q {q}");
            for d in 0..2 * q {
                let got: f64 = z.iter().zip(&w).map(|(x, wi)| wi * x.powi(d as i32)).sum();
                let exact = if d % 2 == 1 {
                    0.0
                } else {
                    2.0 / (d as f64 + 1.0)
                };
                assert!(
                    (got - exact).abs() < 1e-13,
                    "q {q} degree {d}: {got} vs {exact}"
                );
            }
        }
    }

    #[test]
    fn integrates_cosine_to_closed_form() {
        // ∫_{−1}^{1} cos(a z) dz = 2 sin(a)/a.
        let (z, w) = gauss_legendre(30);
        for a in [0.5, 3.0, 12.0] {
            let got: f64 = z.iter().zip(&w).map(|(x, wi)| wi * (a * x).cos()).sum();
            assert!((got - 2.0 * f64::sin(a) / a).abs() < 1e-14, "a {a}");
        }
    }

    #[test]
    fn zero_points_is_empty() {
        let (z, w) = gauss_legendre(0);
        assert!(z.is_empty() && w.is_empty());
    }
}
