//! The `statistics` bundle: every stage agrees with its own function, skipped stages say why.

use crate::metrics_common;

use glam::DVec2;
use metrics_common::{random, sobol};
use samplescope::core::cancel::Cancel;
use samplescope::core::metrics::{
    l2_star_discrepancy, min_distance, star_discrepancy, statistics, t_value, MetricsError,
    STATISTICS_STAR_MAX_N,
};

#[test]
fn bundle_agrees_with_each_function() {
    let c = Cancel::never();
    for pts in [sobol(256), random(256, 4)] {
        let s = statistics(&pts, &c).unwrap();
        assert_eq!(s.n, 256);
        assert_eq!(s.min_distance, Some(min_distance(&pts, &c).unwrap()));
        assert_eq!(s.star, Some(star_discrepancy(&pts, &c).unwrap()));
        assert_eq!(s.l2_star, l2_star_discrepancy(&pts, &c).unwrap());
        assert_eq!(s.t_value, Some(t_value(&pts, 2, &c).unwrap()));
        assert!(s.min_distance_skipped.is_none() && s.star_skipped.is_none());
        assert!(s.t_value_skipped.is_none());
        let names: Vec<&str> = s.timings.iter().map(|t| t.0).collect();
        assert_eq!(
            names,
            [
                "min distance",
                "star discrepancy",
                "L2-star discrepancy",
                "t-value"
            ]
        );
        let json = serde_json::to_string(&s).unwrap();
        assert!(json.contains("\"timings\""));
    }
    assert_eq!(statistics(&sobol(256), &c).unwrap().t_value.unwrap().t, 0);
}

#[test]
fn single_point_skips_min_distance() {
    let s = statistics(&[DVec2::new(0.5, 0.5)], &Cancel::never()).unwrap();
    assert!(s.min_distance.is_none());
    assert!(s
        .min_distance_skipped
        .unwrap()
        .contains("at least 2 points"));
    assert_eq!(s.star.unwrap().value, 0.75);
    assert_eq!(s.t_value.unwrap().t, 0); // 1 = 2⁰
}

#[test]
fn n_not_power_of_two_skips_t_value() {
    let s = statistics(&random(100, 1), &Cancel::never()).unwrap();
    assert!(s.t_value.is_none());
    assert!(s.t_value_skipped.unwrap().contains("not a power of 2"));
    assert_eq!(s.timings.len(), 3);
}

#[test]
fn large_n_skips_exact_star() {
    let n = STATISTICS_STAR_MAX_N + 1;
    let s = statistics(&random(n, 2), &Cancel::never()).unwrap();
    assert!(s.star.is_none());
    assert!(s.star_skipped.unwrap().contains("O(N²)"));
    assert!(s.min_distance.is_some());
    assert!(s.l2_star > 0.0);
}

#[test]
fn errors_propagate() {
    let c = Cancel::never();
    assert_eq!(statistics(&[], &c), Err(MetricsError::Empty));
    let mut pts = random(10, 3);
    pts[9] = DVec2::new(0.5, f64::NAN);
    assert!(matches!(
        statistics(&pts, &c),
        Err(MetricsError::NonFinite { index: 9, .. })
    ));
    let cancelled = Cancel::new();
    cancelled.cancel();
    assert_eq!(
        statistics(&random(10, 3), &cancelled),
        Err(MetricsError::Cancelled)
    );
}
