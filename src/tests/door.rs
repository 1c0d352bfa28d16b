//! The door (`Solver`): numerical failures, warm start by contact ids, a device handed in, bad input named.

use crate::settings::Method;
use crate::solver::*;
use crate::{Backend, Lcp, Settings};
use crate::{Body, Contact, SolvePath, Status};

fn cpu(method: Method) -> Solver {
    Solver::new(Settings::new(Backend::Cpu, method)).unwrap()
}

#[test]
fn an_overflowing_answer_is_a_numerical_failure_for_every_method() {
    // z = 1e10 / 1e-300 overflows f64; 5e-324 is the smallest subnormal.
    for m in [1e-300, 5e-324] {
        let lcp = Lcp::new(vec![m], vec![-1e10]).unwrap();
        for method in [Method::Enumeration, Method::Lemke, Method::Pgs] {
            let r = cpu(method).solve_lcps(std::slice::from_ref(&lcp)).unwrap();
            let s = r.islands[0].status();
            assert!(
                !s.is_solution(),
                "{method:?} on M = {m:e}: {s} z = {:?}",
                r.islands[0].solution.z
            );
            assert_eq!(r.max_error, None, "{method:?}");
            if method != Method::Pgs {
                assert_eq!(s, Status::NumericalFailure, "{method:?}");
                assert_eq!(r.statuses[6], 1);
            }
        }
    }
}

#[test]
fn warm_start_by_contact_ids_settles_the_next_call_and_gives_the_same_impulses() {
    // A box resting on 4 coplanar contacts (M singular: no prediction).
    let mut scene = crate::generate::box_on_ground(1.0, 0.0);
    for (k, c) in scene.contacts.iter_mut().enumerate() {
        c.id = Some(100 + k as u64);
    }
    let mut solver = Solver::new(Settings {
        warm_start: true,
        ..Settings::new(Backend::Cpu, Method::Enumeration)
    })
    .unwrap();
    let cold = solver.solve_scenes(std::slice::from_ref(&scene)).unwrap();
    let hot = solver.solve_scenes(std::slice::from_ref(&scene)).unwrap();
    assert_eq!(cold.scenes[0].impulses, hot.scenes[0].impulses);
    assert_ne!(cold.islands[0].path, SolvePath::WarmStart);
    assert_eq!(hot.islands[0].path, SolvePath::WarmStart);
    assert_eq!(hot.counts.warm_start, hot.islands.len());
    // Without ids nothing is remembered.
    let mut plain = Solver::new(Settings {
        warm_start: true,
        ..Settings::new(Backend::Cpu, Method::Enumeration)
    })
    .unwrap();
    let anonymous = crate::generate::box_on_ground(1.0, 0.0);
    plain
        .solve_scenes(std::slice::from_ref(&anonymous))
        .unwrap();
    let again = plain.solve_scenes(&[anonymous]).unwrap();
    assert_eq!(again.counts.warm_start, 0);
}

#[test]
fn keyed_lcps_check_their_ids_and_warm_start() {
    let lcp = Lcp::new(vec![2.0, 1.0, 1.0, 2.0], vec![-5.0, -6.0]).unwrap();
    let mut solver = Solver::new(Settings {
        warm_start: true,
        predict: true,
        ..Settings::new(Backend::Cpu, Method::Enumeration)
    })
    .unwrap();
    let e = solver
        .solve_lcps_keyed(std::slice::from_ref(&lcp), &[vec![1]])
        .unwrap_err();
    assert!(e.to_string().contains("problem 0"), "{e}");
    let ids = vec![vec![7, 8]];
    let first = solver
        .solve_lcps_keyed(std::slice::from_ref(&lcp), &ids)
        .unwrap();
    let second = solver
        .solve_lcps_keyed(std::slice::from_ref(&lcp), &ids)
        .unwrap();
    assert_eq!(first.islands[0].solution.z, second.islands[0].solution.z);
    assert_eq!(second.islands[0].path, SolvePath::WarmStart);
    solver.clear_warm_start();
    let third = solver.solve_lcps_keyed(&[lcp], &ids).unwrap();
    assert_ne!(third.islands[0].path, SolvePath::WarmStart);
}

#[test]
fn a_device_handed_in_is_used_and_gives_the_cpus_answers() {
    let Some(gpu) = crate::tests::common::gpu_settings_or_skip() else {
        return;
    };
    let device = crate::GpuContext::open(&gpu).unwrap();
    let mut s = Solver::with_device(Settings::default(), device).unwrap();
    assert_ne!(s.device().kind, crate::DeviceKind::Cpu);
    let lcp = Lcp::new(vec![2.0, 1.0, 1.0, 2.0], vec![-5.0, -6.0]).unwrap();
    let r = s.solve_lcps(std::slice::from_ref(&lcp)).unwrap();
    assert!(r.on_gpu() && r.gpu.is_some());
    let c = cpu(Method::Enumeration).solve_lcps(&[lcp]).unwrap();
    assert_eq!(r.islands[0].solution.basis, c.islands[0].solution.basis);
    assert!((r.islands[0].solution.z[0] - 4.0 / 3.0).abs() < 1e-12);
}

#[test]
fn bad_input_is_an_error_naming_the_item() {
    let bad = Lcp {
        m: vec![1.0, f64::NAN, 0.0, 1.0],
        q: vec![1.0, -1.0],
    };
    let good = Lcp::new(vec![1.0], vec![-1.0]).unwrap();
    let e = cpu(Method::Lemke)
        .solve_lcps(&[good.clone(), bad.clone()])
        .unwrap_err();
    assert!(e.to_string().contains("problem 1"), "{e}");
    // Checks come before the size limit, whatever the order in the batch.
    let big = Lcp::new(vec![0.0; 21 * 21], vec![1.0; 21]).unwrap();
    let e = cpu(Method::Enumeration)
        .solve_lcps(&[big.clone(), bad])
        .unwrap_err();
    assert!(e.to_string().contains("problem 1: field `M[0][1]`"), "{e}");
    let e = cpu(Method::Enumeration)
        .solve_lcps(&[good, big])
        .unwrap_err();
    assert!(
        e.to_string().contains("problem 1: enumeration visits"),
        "{e}"
    );
    let scene = crate::Scene {
        bodies: vec![Body::new(1.0, [1.0; 3], [0.0; 3])],
        contacts: vec![Contact::new(3, None, [0.0; 3], [0.0, 1.0, 0.0], 0.5)],
    };
    let e = cpu(Method::Enumeration).solve_scenes(&[scene]).unwrap_err();
    assert!(e.to_string().contains("scene 0"), "{e}");
}
