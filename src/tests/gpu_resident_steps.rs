//! Many steps per call (`Solver::step_worlds_for`, issue 23): the states
//! stay on the device for the call, steps go several to a submission, and
//! the trajectory and every step's report are bit for bit those of one
//! `step_worlds` call per step, on the resident path in f64 on lavapipe
//! (frictionless, and with friction by `pgs` warm-started), on the CPU
//! path, with a world flagged in the middle of a submission (a forced
//! overflow of its contact slots: the submission is undone and taken again
//! a step at a time), and with the device lost in the middle of a call
//! (the CPU path takes the call again from the worlds passed in). An
//! undone submission restores the records (the solve stages' warm bases
//! live there); a call's frames read only their worlds' states. Skipped
//! without an f64 adapter (the CPU tests always run).

use super::gpu_resident::{f64_gpu, frictionless, max_distance, settings};
use super::gpu_resident_friction::{frictional, settings as friction_settings};
use crate::friction::FrictionMethod;
use crate::gpu::resident::layout::flags;
use crate::gpu::resident::{ResidentWorlds, WorldRecord};
use crate::gpu::{GpuContext, GpuOptions, Precision};
use crate::solver::world_gpu::{accepted, set_test_slots};
use crate::world::generate::WorldKind;
use crate::world::World;
use crate::world::WorldStepReport;
use crate::{Backend, Frames, GpuSettings, Settings, Solver, StepReport};

/// `worlds` stepped `steps` times by one `step_worlds` call per step:
/// the worlds after, each step's reports.
fn one_call_per_step(
    s: &Settings,
    mut worlds: Vec<World>,
    steps: usize,
) -> (Vec<World>, Vec<StepReport>) {
    let mut solver = Solver::new(s.clone()).unwrap();
    let reports = (0..steps)
        .map(|_| solver.step_worlds(&mut worlds, 0.01).unwrap())
        .collect();
    (worlds, reports)
}

/// `worlds` stepped `steps` times by `step_worlds_for` calls of `calls`
/// steps each (the last one the rest): the worlds after, each step's
/// reports (the steps numbered in order checked).
fn calls_of(
    s: &Settings,
    mut worlds: Vec<World>,
    steps: usize,
    calls: usize,
) -> (Vec<World>, Vec<StepReport>) {
    let mut solver = Solver::new(s.clone()).unwrap();
    let mut reports = Vec::new();
    let mut done = 0;
    while done < steps {
        let n = calls.min(steps - done);
        let mut seen = 0;
        solver
            .step_worlds_for(&mut worlds, 0.01, n, |step, r| {
                assert_eq!(step, seen, "steps reported in order");
                seen += 1;
                reports.push(r);
            })
            .unwrap();
        assert_eq!(seen, n);
        done += n;
    }
    (worlds, reports)
}

/// The per-world figures of every step.
fn figures(reports: &[StepReport]) -> Vec<Vec<WorldStepReport>> {
    reports.iter().map(|r| r.worlds.clone()).collect()
}

/// `step_worlds_for` in calls of 1000, 7 and 1 steps gives the worlds and
/// the per-world figures of one `step_worlds` call per step, bit for bit;
/// returns the worlds after and the reports of the single call.
fn same_as_one_call_per_step(
    s: &Settings,
    worlds: Vec<World>,
    steps: usize,
) -> (Vec<World>, Vec<StepReport>) {
    let (want, want_reports) = one_call_per_step(s, worlds.clone(), steps);
    let mut first = Vec::new();
    for calls in [1000, 7, 1] {
        let (got, reports) = calls_of(s, worlds.clone(), steps, calls);
        assert_eq!(reports.len(), steps);
        assert!(got == want, "calls of {calls}: the worlds differ");
        assert!(
            figures(&reports) == figures(&want_reports),
            "calls of {calls}: the figures differ"
        );
        for (a, b) in reports.iter().zip(&want_reports) {
            assert_eq!((a.unsolved, a.repairs), (b.unsolved, b.repairs));
        }
        if first.is_empty() {
            first = reports;
        }
    }
    (want, first)
}

/// Bytes read back in a call of `steps` where no world was flagged: per
/// step and world the record (8 scalars and 4 words), every state once
/// (13 scalars and 2 words a body).
fn clean_call_bytes(worlds: &[World], steps: usize) -> u64 {
    let bodies: usize = worlds.iter().map(|w| w.bodies.len()).sum();
    (steps * worlds.len() * (8 * 8 + 16) + bodies * (13 * 8 + 8)) as u64
}

#[test]
fn on_the_cpu_many_steps_are_one_call_per_step() {
    let mut worlds = frictionless(WorldKind::Stack, 3, 2);
    worlds.extend(frictional(WorldKind::Slide, 1, 1));
    let s = settings(Backend::Cpu, GpuSettings::default());
    let (_, reports) = same_as_one_call_per_step(&s, worlds, 40);
    assert!(reports.iter().all(|r| r.resident.is_none()));
}

#[test]
fn frictionless_worlds_take_many_steps_per_submission_bit_for_bit() {
    let Some(gpu) = f64_gpu() else { return };
    let mut worlds = frictionless(WorldKind::Stack, 4, 1);
    worlds.extend(frictionless(WorldKind::Stack, 2, 1));
    worlds.extend(frictionless(WorldKind::Spheres, 4, 2));
    let steps = 60;
    let (_, reports) =
        same_as_one_call_per_step(&settings(Backend::Gpu, gpu), worlds.clone(), steps);
    let f: Vec<_> = reports
        .iter()
        .map(|r| r.resident.expect("resident"))
        .collect();
    assert!(f.iter().all(|x| x.on_cpu == 0), "no world flagged");
    // Submissions of 1, 2, 4, 8, 16, 16, 13 steps.
    let most = f.iter().map(|x| x.submission_steps).max().unwrap();
    assert_eq!(most, 16);
    let bytes: u64 = f.iter().map(|x| x.bytes_back).sum();
    assert_eq!(bytes, clean_call_bytes(&worlds, steps));
    // One call per step reads every state every step.
    let (_, single) = one_call_per_step(
        &settings(Backend::Gpu, f64_gpu().unwrap()),
        worlds.clone(),
        3,
    );
    let per_step = single[2].resident.unwrap().bytes_back;
    assert_eq!(per_step, clean_call_bytes(&worlds, 1));
}

#[test]
fn frictional_worlds_take_many_steps_per_submission_bit_for_bit() {
    let Some(gpu) = f64_gpu() else { return };
    let mut worlds = frictional(WorldKind::Stack, 2, 1);
    worlds.extend(frictional(WorldKind::Stack, 3, 1));
    worlds.extend(frictional(WorldKind::Slide, 1, 1));
    let s = Settings {
        friction_tolerance: 1e-6,
        ..friction_settings(gpu, FrictionMethod::Pgs, true)
    };
    let (_, reports) = same_as_one_call_per_step(&s, worlds, 60);
    let f: Vec<_> = reports
        .iter()
        .map(|r| r.resident.expect("resident"))
        .collect();
    let on_device: usize = f.iter().map(|x| x.on_device).sum();
    println!("pgs, warm-started: {on_device} world-steps of 180 on the device");
    assert!(
        f.iter().any(|x| x.submission_steps > 1),
        "several steps per submission"
    );
}

/// A box falls onto the ground through a contact budget of 2 slots: the
/// submission in which it lands is undone and taken again a step at a
/// time, the box stepped on the CPU from then on; spheres beside it stay on
/// the device. Bit for bit one call per step, within 1e-9 m of the CPU
/// path.
#[test]
fn a_world_flagged_within_a_submission_is_taken_again_a_step_at_a_time() {
    let Some(gpu) = f64_gpu() else { return };
    let mut worlds = frictionless(WorldKind::Stack, 1, 1);
    worlds[0].bodies[1].position[1] += 0.3;
    worlds.extend(frictionless(WorldKind::Spheres, 1, 2));
    let s = settings(Backend::Gpu, gpu);
    set_test_slots(Some(2));
    let (got, reports) = same_as_one_call_per_step(&s, worlds.clone(), 50);
    set_test_slots(None);
    let f: Vec<_> = reports
        .iter()
        .map(|r| r.resident.expect("resident"))
        .collect();
    let landed = f.iter().position(|x| x.on_cpu > 0).expect("the box lands");
    assert!(
        landed > 8,
        "landed in step {landed}, after a submission of 8"
    );
    assert!(f[landed..]
        .iter()
        .all(|x| x.contacts_full == 1 && x.submission_steps == 1));
    assert!(f[..landed].iter().any(|x| x.submission_steps > 1));
    let cpu = settings(Backend::Cpu, GpuSettings::default());
    let (want, _) = one_call_per_step(&cpu, worlds, 50);
    let d = max_distance(&got, &want);
    assert!(d < 1e-9, "{d} m from the CPU path");
}

/// The device is lost after step 29 of a call of 60 is reported (the
/// submission of steps 15 to 30 has run and its steps are reported as it
/// ends): the CPU path takes the call again from the worlds passed in,
/// reporting steps 31 to 59; the worlds end as the CPU path leaves them,
/// bit for bit.
#[test]
fn a_device_lost_within_a_call_hands_the_call_to_the_cpu() {
    let Some(gpu) = f64_gpu() else { return };
    let worlds = frictionless(WorldKind::Spheres, 4, 2);
    let (want, _) = one_call_per_step(
        &settings(Backend::Cpu, GpuSettings::default()),
        worlds.clone(),
        60,
    );
    let mut g = Solver::new(settings(Backend::Gpu, gpu)).unwrap();
    let device = g.shared_device().unwrap();
    let mut got = worlds;
    let mut steps = Vec::new();
    g.step_worlds_for(&mut got, 0.01, 60, |step, r| {
        steps.push((step, r.resident.is_some()));
        if step == 29 {
            device.simulate_device_loss();
        }
    })
    .unwrap();
    let numbers: Vec<usize> = steps.iter().map(|x| x.0).collect();
    assert_eq!(numbers, (0..60).collect::<Vec<_>>());
    assert!(steps[30].1 && !steps[31].1, "steps 31 to 59 on the CPU");
    assert!(g.fallback().is_some());
    assert_eq!(got, want);
}

/// A submission stands where no world was flagged and none needed more
/// rounds than one step per submission would have given it.
#[test]
fn a_submission_stands_only_as_one_step_per_submission_would_go() {
    let rec = |flags, rounds| WorldRecord {
        flags,
        rounds,
        ..WorldRecord::default()
    };
    // Frictionless: no rounds.
    assert_eq!(accepted(0, &[vec![rec(0, 0)], vec![rec(0, 0)]]), Some(0));
    assert_eq!(
        accepted(0, &[vec![rec(0, 0)], vec![rec(flags::CONTACTS_FULL, 0)]]),
        None
    );
    // 16 rounds, a world active in 3: the next step gets 6, and after one
    // active in 4, 6 again (they come down, never up without a hand-over).
    assert_eq!(accepted(16, &[vec![rec(0, 3)], vec![rec(0, 4)]]), Some(6));
    // ... where a world active in 7 would have been handed to the CPU.
    assert_eq!(accepted(16, &[vec![rec(0, 3)], vec![rec(0, 7)]]), None);
}

/// The solve stages' warm basis of each world (the last two of its record's
/// scalars) in the records buffer as it is now.
fn warm_bases(r: &ResidentWorlds, ctx: &GpuContext) -> Vec<[f64; 2]> {
    let rec = r.records_now(ctx).unwrap();
    let per = crate::gpu::resident::layout::REC;
    rec.chunks(per).map(|x| [x[per - 2], x[per - 1]]).collect()
}

/// A box lands within a submission of 16 steps, its warm basis changing
/// from none to its contacts'; the submission is undone: the records, the
/// warm bases with them, are as before it (and not as after), so the steps
/// taken again start from the bases one step per submission had.
#[test]
fn an_undone_submission_restores_the_warm_bases() {
    if f64_gpu().is_none() {
        return;
    }
    let ctx = GpuContext::new(&GpuOptions {
        precision: Precision::F64,
        ..GpuOptions::from_env().unwrap()
    })
    .unwrap();
    let mut worlds = frictionless(WorldKind::Stack, 1, 1);
    worlds[0].bodies[1].position[1] += 0.3;
    worlds.extend(frictionless(WorldKind::Stack, 2, 1));
    let gpu = Settings::default().gpu_solve();
    let r = ResidentWorlds::new(&ctx, &worlds, 1e-8, &gpu, true, None, None).unwrap();
    // Falls 0.3 m: lands after about 25 steps of 10 ms.
    for _ in 0..15 {
        assert!(r.step(&ctx, 0.01).unwrap().iter().all(|x| x.flags == 0));
    }
    let before_records = r.records_now(&ctx).unwrap();
    let before = warm_bases(&r, &ctx);
    let history = r.steps(&ctx, 0.01, 16).unwrap();
    let landed = history.iter().position(|x| x[0].contacts > 0);
    assert!(
        landed.is_some_and(|j| j > 0),
        "the box lands within: {landed:?}"
    );
    let after = warm_bases(&r, &ctx);
    assert_ne!(after[0], before[0], "the landing box's warm basis changed");
    r.restore(&ctx).unwrap();
    assert_eq!(warm_bases(&r, &ctx), before);
    assert!(r.records_now(&ctx).unwrap() == before_records);
}

/// A call with frames on the resident path: the frames' worlds and
/// figures are those of one `step_worlds` call per step at those steps,
/// bit for bit; only the frames' worlds come back for a frame (bytes).
#[test]
fn frames_read_only_their_worlds() {
    let Some(gpu) = f64_gpu() else { return };
    let mut worlds = frictionless(WorldKind::Stack, 4, 3);
    worlds.extend(frictionless(WorldKind::Spheres, 3, 3));
    let s = settings(Backend::Gpu, gpu);
    let steps = 40;
    let shown = [1usize, 4];
    let at = |s: usize| s.is_multiple_of(15) || s == 40;
    let mut solver = Solver::new(s.clone()).unwrap();
    let (mut cpu_solver, mut want) = (Solver::new(s).unwrap(), worlds.clone());
    let mut want_frames = Vec::new();
    for step in 1..=steps {
        cpu_solver.step_worlds(&mut want, 0.01).unwrap();
        if at(step) {
            want_frames.push((step, shown.map(|k| want[k].clone()).to_vec()));
        }
    }
    let (mut frames, mut bytes) = (Vec::new(), 0);
    let mut got = worlds.clone();
    let f = Frames {
        worlds: &shown,
        at: &at,
    };
    let observe = |_, r: StepReport| bytes += r.resident.expect("resident").bytes_back;
    let show = |s: usize, w: &[World]| frames.push((s, w.to_vec()));
    (solver.step_worlds_framed(&mut got, 0.01, steps, f, observe, show)).unwrap();
    assert!(frames == want_frames, "the frames");
    assert!(got == want, "the worlds after");
    // Frames after steps 15 and 30 read the two worlds' bodies (that of
    // step 40 is the call's end, which reads every state).
    let bodies: usize = shown.iter().map(|&k| worlds[k].bodies.len()).sum();
    let frame_bytes = 2 * bodies * (13 * 8 + 8);
    assert_eq!(bytes, clean_call_bytes(&worlds, steps) + frame_bytes as u64);
    // A frame's world out of the batch is refused, nothing stepped.
    let f = Frames {
        worlds: &[9],
        at: &at,
    };
    let err = solver.step_worlds_framed(&mut got, 0.01, 1, f, |_, _| {}, |_, _| {});
    assert!(err.unwrap_err().to_string().contains("frames"));
    assert!(got == want);
}

/// The same frames on the CPU path: copies of the worlds as they step.
#[test]
fn frames_on_the_cpu_are_the_worlds_as_they_step() {
    let worlds = frictionless(WorldKind::Spheres, 3, 3);
    let s = settings(Backend::Cpu, GpuSettings::default());
    let (want, _) = one_call_per_step(&s, worlds.clone(), 7);
    let mut solver = Solver::new(s).unwrap();
    let mut got = worlds;
    let mut frames = Vec::new();
    let f = Frames {
        worlds: &[2],
        at: &|s| s == 7,
    };
    let show = |s: usize, w: &[World]| frames.push((s, w.to_vec()));
    (solver.step_worlds_framed(&mut got, 0.01, 7, f, |_, _| {}, show)).unwrap();
    assert!(got == want);
    assert!(frames == vec![(7, vec![want[2].clone()])]);
}
