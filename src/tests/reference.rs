//! The tests' reference, in the door's vocabulary ([`Method`],
//! [`Settings`], [`Report`]): one LCP solved by the one algorithm
//! `settings.method` names ([`solve`]: the library's `enumerate`, `lemke`
//! or `pgs`, as the algorithm answers, without the door's final check),
//! one scene solved on the CPU by the door ([`solve_scene`]), and a scene's
//! build ([`build`]). The batched and GPU solves are compared with them.

use crate::build::Built;
use crate::cpu::assembly::ContactRow;
use crate::cpu::enumeration::enumerate;
use crate::cpu::lemke::lemke;
use crate::cpu::pgs::pgs;
use crate::islands::Island;
use crate::lcp::{Lcp, LcpSolution};
use crate::scene::Scene;
use crate::settings::{Backend, Method, Settings};
use crate::{Error, Report};

/// Checks a scene and builds it: islands, contact rows and island LCPs.
pub fn build(scene: &Scene, item: &str) -> Result<(Vec<Island>, Vec<ContactRow>, Vec<Lcp>), Error> {
    scene.validate(item)?;
    let b = Built::new(scene);
    Ok((b.islands, b.rows, b.lcps))
}

/// Solves one LCP with the algorithm `settings.method` names, configured
/// by `settings`: enumeration (after prediction with `settings.predict`,
/// as the GPU path does, so that both report the same result and
/// counters; not with `all_solutions`), Lemke or PGS. Errors only when the
/// algorithm cannot take the problem at all (enumeration beyond its size
/// limit, settings out of range) and for [`Method::Auto`], which is the
/// door's choice among algorithms, not one of them; everything else is a
/// status on the solution.
pub fn solve(lcp: &Lcp, settings: &Settings) -> Result<LcpSolution, Error> {
    match settings.method {
        Method::Enumeration => {
            let e = settings.enumeration();
            if settings.predict && !e.all_solutions {
                e.validate()?;
                if let Some((_, solution)) = crate::prediction::predict(lcp, None, &e) {
                    return Ok(solution);
                }
            }
            enumerate(lcp, &e)
        }
        Method::Lemke => Ok(lemke(lcp, &settings.lemke())),
        Method::Pgs => Ok(pgs(lcp, &settings.pgs())),
        Method::Auto => Err(Error::Unsupported(
            "the tests' reference solves with one algorithm; name enumeration, Lemke or PGS".into(),
        )),
    }
}

/// Solves one frictionless scene on the CPU through the door
/// ([`crate::Solver`] with `settings`, its backend made [`Backend::Cpu`]):
/// every island with the chosen method (enumeration hands islands above
/// n = 20 to Lemke), then the impulses. The report's only scene is
/// `scenes[0]`; its `islands` are the scene's, in the order of [`build`]'s.
pub fn solve_scene(scene: &Scene, settings: &Settings) -> Result<Report, Error> {
    assert!(
        !scene.has_friction(),
        "the reference solves frictionless scenes"
    );
    let mut solver = crate::Solver::new(Settings {
        backend: Backend::Cpu,
        ..settings.clone()
    })?;
    solver.solve_scenes(std::slice::from_ref(scene))
}
