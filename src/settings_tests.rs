//! The settings' table-driven test and the names' round trips.

/// `parse` is the inverse of `name` on every value, and anything else
/// is an error naming the field and listing every name.
fn round_trip<T: Copy + PartialEq + std::fmt::Debug + FromStr<Err = Error>>(
    all: &[T],
    name: fn(T) -> &'static str,
    field: &str,
    listed: &str,
) {
    for &v in all {
        assert_eq!(name(v).parse::<T>().unwrap(), v, "{}", name(v));
    }
    for bad in ["", "Auto", "gpu ", "enumeration", "sor"] {
        let e = bad.parse::<T>().unwrap_err().to_string();
        assert_eq!(
            e,
            format!("{field}: field `{field}`: `{bad}` is not one of {listed}")
        );
    }
}

#[test]
fn backend_parses_its_names() {
    round_trip(&Backend::ALL, Backend::name, "backend", "auto, cpu, gpu");
}

#[test]
fn method_parses_its_names() {
    round_trip(
        &Method::ALL,
        Method::name,
        "method",
        "auto, enum, lemke, pgs",
    );
}

#[test]
fn friction_method_parses_its_names() {
    round_trip(
        &FrictionMethod::ALL,
        FrictionMethod::name,
        "friction_method",
        "auto, nsgs, newton, prox, jacobi, pgs, apgd",
    );
}

#[test]
fn precision_parses_its_names() {
    round_trip(
        &Precision::ALL,
        Precision::name,
        "precision",
        "auto, f32, f64",
    );
    // The environment's spelling is any case.
    assert_eq!(Precision::parse("F64").unwrap(), Precision::F64);
}
use super::*;

#[test]
fn defaults_are_valid_and_each_bad_value_names_its_field() {
    Settings::default().validate().unwrap();
    let cases: Vec<(&str, Settings)> = vec![
        (
            "pivot_tol",
            Settings {
                pivot_tol: 1.0,
                ..Default::default()
            },
        ),
        (
            "feasibility_tol",
            Settings {
                feasibility_tol: f64::NAN,
                ..Default::default()
            },
        ),
        (
            "relaxed_feasibility_tol",
            Settings {
                relaxed_feasibility_tol: 1e-14,
                ..Default::default()
            },
        ),
        (
            "lemke_max_pivots",
            Settings {
                lemke_max_pivots: 0,
                ..Default::default()
            },
        ),
        (
            "warm_start_calls",
            Settings {
                warm_start_calls: 0,
                ..Default::default()
            },
        ),
        (
            "lemke_pivot_tol",
            Settings {
                lemke_pivot_tol: -1.0,
                ..Default::default()
            },
        ),
        (
            "pgs_max_sweeps",
            Settings {
                pgs_max_sweeps: 0,
                ..Default::default()
            },
        ),
        (
            "pgs_tolerance",
            Settings {
                pgs_tolerance: f64::INFINITY,
                ..Default::default()
            },
        ),
        (
            "all_solutions",
            Settings {
                all_solutions: true,
                method: Method::Lemke,
                ..Default::default()
            },
        ),
        ("backend", Settings::new(Backend::Gpu, Method::Pgs)),
        (
            "friction_tolerance",
            Settings {
                friction_tolerance: 0.0,
                ..Default::default()
            },
        ),
        (
            "friction_max_iterations",
            Settings {
                friction_max_iterations: 0,
                ..Default::default()
            },
        ),
    ];
    for (field, s) in cases {
        let e = s.validate().expect_err(field).to_string();
        assert!(e.contains(field), "{field}: {e}");
    }
    let mut s = Settings::default();
    s.gpu.max_workgroups = Some(0);
    assert!(s
        .validate()
        .unwrap_err()
        .to_string()
        .contains("gpu.max_workgroups"));
}
