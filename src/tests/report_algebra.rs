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

/// What a report says, to compare two: per island (scene, path, z), per
/// frictional island (scene, contacts), per scene its ranges and impulses,
/// the counts, statuses and largest errors with their index.
fn contents(r: &crate::report::Report) -> String {
    let islands: Vec<_> = r
        .islands
        .iter()
        .map(|i| (i.scene, i.path, i.solution.z.to_vec()))
        .collect();
    let friction: Vec<_> = r.friction.iter().map(|i| (i.scene, &i.contacts)).collect();
    let scenes: Vec<_> = r
        .scenes
        .iter()
        .map(|s| {
            let range = s.friction.as_ref().map(|f| f.islands.clone());
            (s.islands.clone(), range, &s.impulses)
        })
        .collect();
    format!(
        "{islands:?}\n{friction:?}\n{scenes:?}\n{:?} {:?} {:?} {:?} {:?}",
        r.counts, r.statuses, r.max_error, r.friction_statuses, r.max_coulomb_error
    )
}

/// Scenes solved in two interleaved parts and merged scene by scene are
/// the batch solved at once: islands move with their scenes, scenes
/// without islands get the empty range where they stand.
#[test]
fn scenes_merged_in_the_callers_order_are_the_whole() {
    let mut rng = Rng::new(11);
    let mut scenes: Vec<_> = (0..7)
        .map(|k| random_scene(&mut rng, 2 + k % 3, 3 + k, 10.0))
        .collect();
    scenes.insert(
        3,
        crate::Scene {
            bodies: Vec::new(),
            contacts: Vec::new(),
        },
    );
    let mut solver = Solver::new(Settings::new(Backend::Cpu, Method::Auto)).unwrap();
    let whole = solver.solve_scenes(&scenes).unwrap();
    for pattern in [0b0101_0110u32, 0b1111_0000, 0b0000_0001, 0b1010_1010] {
        let from_other: Vec<bool> = (0..scenes.len()).map(|k| pattern >> k & 1 == 1).collect();
        let part = |o: bool| -> Vec<crate::Scene> {
            let picked = scenes.iter().zip(&from_other).filter(|(_, &f)| f == o);
            picked.map(|(s, _)| s.clone()).collect()
        };
        let mut merged = solver.solve_scenes(&part(false)).unwrap();
        merged.merge_scenes(solver.solve_scenes(&part(true)).unwrap(), &from_other);
        assert_eq!(contents(&merged), contents(&whole), "pattern {pattern:b}");
    }
}

/// A report rebuilt scene by scene with `push_scene` (islands and
/// frictional islands with their scene) is the report it came from.
#[test]
fn scenes_pushed_one_by_one_are_the_whole() {
    let mut rng = Rng::new(5);
    let scenes = vec![
        random_scene(&mut rng, 3, 5, 10.0),
        box_stack(3, 0.5, 0.1, 0.0),
        box_on_ground(1.0, 0.0),
        box_stack(2, 0.3, 0.2, 0.01),
    ];
    let mut solver = Solver::new(Settings::new(Backend::Cpu, Method::Auto)).unwrap();
    let whole = solver.solve_scenes(&scenes).unwrap();
    let mut pushed = solver.solve_scenes(&[]).unwrap();
    for s in &whole.scenes {
        let islands = whole.islands[s.islands.clone()].to_vec();
        let range = s.friction.as_ref().map_or(0..0, |f| f.islands.clone());
        pushed.push_scene(s.clone(), islands, whole.friction[range].to_vec());
    }
    assert_eq!(contents(&pushed), contents(&whole));
}
