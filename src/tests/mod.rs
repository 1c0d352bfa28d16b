//! The crate's tests that reach past the public face: each GPU stage against
//! its CPU twin, the CPU solvers against worked examples of the LCP texts
//! and the Siconos problems, physics identities, stress families, device trouble.
//! Shared helpers live in [`common`]. (The tests of the command-line tool
//! and of the recorded output are in `tests/`.)

pub(crate) mod common;
pub(crate) mod reference;
pub(crate) mod skip;

mod device_trouble;
mod door;
mod friction;
mod friction_conformance;
mod friction_conformance_large;
mod friction_hard;
mod gpu_all_solutions;
mod gpu_check;
mod gpu_collide;
mod gpu_conformance;
mod gpu_cost_model;
mod gpu_friction;
mod gpu_friction_assembly;
mod gpu_friction_door;
mod gpu_lemke;
mod gpu_pipeline;
mod gpu_prediction;
mod gpu_resident;
mod gpu_resident_friction;
mod gpu_resident_steps;
mod gpu_seeds;
mod gpu_stages;
mod gpu_stress;
mod gpu_tree;
mod gpu_unrolled;
mod gpu_workgroup;
mod gradient;
mod physics;
mod physics_invariance;
mod random_crosscheck;
mod report_algebra;
mod seeds;
mod siconos;
mod stress;
mod stress_gpu_f32;
mod world;
mod world_friction;
mod world_impacts;
mod world_rain;
