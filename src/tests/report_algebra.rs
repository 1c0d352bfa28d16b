//! The report algebra: `Report::append` against solving the whole batch at once.

use crate::generate::friction::box_stack;
use crate::generate::{box_on_ground, random_scene, Rng};
use crate::{Backend, Method, Settings, Solver};

/// A batch solved in parts and joined by `append` is the batch solved
/// at once: islands (scene indices), scenes (island ranges, frictional
/// ones too), counts, statuses and the largest errors with their index.
#[test]
fn appended_parts_are_the_whole() {
    let mut rng = Rng::new(7);
    let mut scenes = vec![
        random_scene(&mut rng, 3, 5, 10.0),
        box_stack(3, 0.5, 0.1, 0.0),
    ];
    scenes.push(box_on_ground(1.0, 0.0));
    scenes.push(random_scene(&mut rng, 4, 6, 100.0));
    scenes.push(box_stack(2, 0.3, 0.2, 0.01));
    let mut solver = Solver::new(Settings::new(Backend::Cpu, Method::Auto)).unwrap();
    let whole = solver.solve_scenes(&scenes).unwrap();
    for cut in 1..scenes.len() {
        let mut joined = solver.solve_scenes(&scenes[..cut]).unwrap();
        joined.append(solver.solve_scenes(&scenes[cut..]).unwrap());
        assert_eq!(joined.counts, whole.counts, "cut {cut}");
        assert_eq!(joined.statuses, whole.statuses, "cut {cut}");
        assert_eq!(joined.max_error, whole.max_error, "cut {cut}");
        assert_eq!(joined.friction_statuses, whole.friction_statuses);
        assert_eq!(joined.max_coulomb_error, whole.max_coulomb_error);
        let scene_of = |r: &crate::report::Report| -> Vec<_> {
            r.islands
                .iter()
                .map(|i| (i.scene, i.solution.z.to_vec()))
                .collect()
        };
        assert_eq!(scene_of(&joined), scene_of(&whole), "cut {cut}");
        let friction_of = |r: &crate::report::Report| -> Vec<_> {
            r.friction
                .iter()
                .map(|i| (i.scene, i.contacts.clone()))
                .collect()
        };
        assert_eq!(friction_of(&joined), friction_of(&whole), "cut {cut}");
        for (a, b) in joined.scenes.iter().zip(&whole.scenes) {
            assert_eq!(a.islands, b.islands, "cut {cut}");
            assert_eq!(a.impulses, b.impulses, "cut {cut}");
            let range =
                |s: &crate::report::SceneReport| s.friction.as_ref().map(|f| f.islands.clone());
            assert_eq!(range(a), range(b), "cut {cut}");
        }
    }
}

/// A NaN error in the appended part replaces a finite maximum (it must
/// show), and the index is the island's in the whole batch.
#[test]
fn a_nan_error_in_the_appended_part_is_the_maximum() {
    let lcp = crate::Lcp::new(vec![2.0], vec![-1.0]).unwrap();
    let mut solver = Solver::new(Settings::new(Backend::Cpu, Method::Auto)).unwrap();
    let mut a = solver.solve_lcps(&[lcp.clone(), lcp.clone()]).unwrap();
    let mut b = solver.solve_lcps(&[lcp]).unwrap();
    b.islands[0].solution.residuals.error = f64::NAN;
    b.max_error = Some((f64::NAN, 0));
    a.append(b);
    let (e, i) = a.max_error.unwrap();
    assert!(e.is_nan());
    assert_eq!(i, 2);
    assert_eq!(a.islands.len(), 3);
    assert_eq!(a.statuses.iter().sum::<usize>(), 3);
}
