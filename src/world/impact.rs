//! Impacts at their time of impact: the part of a world's step
//! ([`super::step::prepare`]) that resolves bouncing contacts where the
//! surfaces meet within the step, before the DVI step sees the world.
//!
//! # Why
//! The DVI step applies every impulse at the step's start, from where the
//! bodies are. A bounce applied there reverses a ball while its surface is
//! still up to one step's travel above the ground, and the ball climbs by
//! that much at every bounce (an elastic ball dropped 0.5 m with Δt = 10 ms
//! gained 3 cm of height, +3%, per bounce).
//!
//! # What is done
//! Within the step every moving body follows the parabola the step's
//! integrator follows: the stored velocity v is the mean velocity over the
//! last step (x₁ = x₀ + Δt v₁, v₁ = v₀ + Δt g), so the body's velocity at
//! the step's start is u = v* − ½Δt g (v* = v + Δt g) and x(t) = x₀ + u t +
//! ½ g t², ending exactly where a free step ends. For every body pair
//! with ε > 0 and no friction (a frictional bounce stays on the DVI step,
//! which has Coulomb's law; this pass has only normal impulses):
//!
//! 1. the time of impact t_c ∈ [t, Δt], the first time the surfaces touch
//!    (gap ≤ [`TOUCH`]) while closing: closed form for sphere–plane (a
//!    quadratic in t) and sphere–sphere under the same gravity (|d + u t| =
//!    r_a + r_b); conservative advancement for every other pair (steps of
//!    gap / a bound on the closing speed, which never steps past contact:
//!    box–box's gap is the separating-axis distance, a lower bound; a pair
//!    touching where it separates is searched on from its points closing
//!    now only);
//! 2. the earliest impact of the world is taken: both bodies advanced to
//!    t_c, the pair's touching points (gap ≤ 2 [`TOUCH`], closing) solved as
//!    one LCP with Newton's restitution and no gap term (Lemke, f64: a
//!    simultaneous impact of a face, one point for a sphere), if it
//!    approaches faster than the step's bounce threshold (slower: a resting
//!    contact, left to the DVI step); the pairs of the two bodies searched
//!    again from t_c; repeated up to [`MAX_IMPACTS`] per world and step
//!    (several bounces in one step, a ball between two others, Newton's
//!    cradle), and an impact still due then is left to the DVI step with
//!    today's bounce (counted as deferred);
//! 3. each body that took an impact is moved on its new parabola to the
//!    step's end (x_e, u_e): the DVI step gets its velocity v* = u_e − ½Δt g
//!    and starts it from the pose x̃ = x_e − Δt v* (orientation likewise),
//!    so that a free step lands it at x_e; each contact's gap becomes the
//!    gap from that pose (linearised), so the DVI step's resting and other
//!    contacts see where the body really ends. A pair that took an impact
//!    separates by its velocity: its contacts get no push out of a
//!    negative gap in this step (b = max(φ, 0)/Δt). The pass lets every
//!    moving body fall, a resting one too, which the DVI step then holds
//!    up; a ball bounced off a resting one could end up to |g|Δt² (1 mm
//!    at 10 ms) inside it, and a push out of that gave it energy (+0.8%
//!    in a ball-on-a-ball run, measured); the next step's contact sees
//!    the ball leaving and does not push it either.
//!
//! Bodies without an impact, and worlds without one, step as before, bit
//! for bit. The pass runs in `prepare`, before the batch is handed to the
//! solver, so the CPU and the GPU path take the same impacts.

use glam::{DMat3, DQuat, DVec3};

use super::collide::{collide_shapes, ContactPoint, Hit, Placed};
use super::step::{integrate_rotation, scene_body};
use super::{Shape, World};
use crate::build::Built;
use crate::cpu::impulses::{apply_impulses, BodyVelocity};
use crate::cpu::lemke::{lemke, LemkeSettings};
use crate::scene::{Contact, Scene};

/// Most impacts resolved at their time in one world's step.
pub const MAX_IMPACTS: usize = 16;

/// Surfaces this close (m) touch: times of impact are found to this gap.
pub const TOUCH: f64 = 1e-6;

/// Steps of conservative advancement before a pair counts as not meeting.
const MAX_ADVANCES: usize = 64;

/// What the impact pass did in one world's step.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Impacts {
    /// Impacts resolved at their time (sub-steps).
    pub count: usize,
    /// Impacts still due when [`MAX_IMPACTS`] was reached (left to the DVI
    /// step, which bounces them from where they are).
    pub deferred: usize,
    /// Per contact (the step's order) the impacts' impulses; empty when
    /// there was none.
    pub impulses: Vec<f64>,
    /// Bodies that took an impact: the pose the DVI step starts them from.
    pub starts: Vec<(usize, DVec3, DQuat)>,
    /// The pairs (a, b) that took an impact.
    pub struck: Vec<(usize, usize)>,
}

impl Impacts {
    /// The pose body `k`'s step starts from, if it took an impact.
    pub fn start(&self, k: usize) -> Option<(DVec3, DQuat)> {
        self.starts.iter().find(|s| s.0 == k).map(|s| (s.1, s.2))
    }

    /// Whether contact `p`'s pair took an impact this step.
    pub fn struck(&self, p: &ContactPoint) -> bool {
        self.struck.contains(&(p.a, p.b))
    }

    /// Contact `p`'s gap from the poses the DVI step starts from: the
    /// collision's where neither body took an impact.
    pub fn gap(&self, world: &World, p: &ContactPoint) -> f64 {
        if self.starts.is_empty() {
            return p.gap;
        }
        let shift = |k: usize| {
            let b = &world.bodies[k];
            self.start(k).map_or(DVec3::ZERO, |(x, q)| {
                x + (q * b.rotation().inverse()) * (p.point - b.position()) - p.point
            })
        };
        p.gap + p.normal.dot(shift(p.a) - shift(p.b))
    }
}

/// A body's motion within the step from time `t`: pose, velocity, and the
/// gravity it falls with (zero for a body that does not move).
#[derive(Clone, Copy, Debug)]
struct Motion {
    t: f64,
    x: DVec3,
    u: DVec3,
    q: DQuat,
    w: DVec3,
    g: DVec3,
}

impl Motion {
    /// The motion at time `s`.
    fn at(&self, s: f64) -> Motion {
        let h = s - self.t;
        Motion {
            t: s,
            x: self.x + self.u * h + self.g * (0.5 * h * h),
            u: self.u + self.g * h,
            q: integrate_rotation(self.q, self.w, h),
            ..*self
        }
    }

    fn placed(&self, shape: Shape) -> Placed {
        Placed {
            shape,
            centre: self.x,
            rotation: DMat3::from_quat(self.q),
        }
    }
}

/// The closing speed of a hit between a and b: (ṗ_a − ṗ_b)·n, negative
/// when closing.
fn closing(a: &Motion, b: &Motion, h: &Hit) -> f64 {
    let pdot = |m: &Motion| m.u + m.w.cross(h.point - m.x);
    (pdot(a) - pdot(b)).dot(h.normal)
}

/// A pair of bodies that may bounce, its ε and its next time of impact.
struct Pair {
    a: usize,
    b: usize,
    eps: f64,
    toi: Option<f64>,
}

/// Resolves the world's impacts within the step (module docs): `v` holds
/// each body's v* and gets the new v* of the bodies that took an impact;
/// `moving`: the bodies the step moves; `threshold`: the bounce threshold.
pub(super) fn resolve_impacts(
    world: &World,
    contacts: &[ContactPoint],
    v: &mut [(DVec3, DVec3)],
    moving: &[bool],
    dt: f64,
    threshold: f64,
) -> Impacts {
    let mut pairs: Vec<Pair> = Vec::new();
    for p in contacts {
        let (ba, bb) = (&world.bodies[p.a], &world.bodies[p.b]);
        let eps = ba.restitution.max(bb.restitution);
        let frictionless = (ba.friction * bb.friction).sqrt() == 0.0;
        let new = pairs.last().is_none_or(|q| (q.a, q.b) != (p.a, p.b));
        if new && eps > 0.0 && frictionless && (moving[p.a] || moving[p.b]) {
            pairs.push(Pair {
                a: p.a,
                b: p.b,
                eps,
                toi: None,
            });
        }
    }
    let mut out = Impacts::default();
    if pairs.is_empty() {
        return out;
    }
    let g = world.gravity();
    let mut motion: Vec<Motion> = world
        .bodies
        .iter()
        .zip(moving)
        .zip(v.iter())
        .map(|((b, &on), &(lin, ang))| {
            let (u, w, g) = match on {
                true => (lin - g * (0.5 * dt), ang, g),
                false => (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO),
            };
            Motion {
                t: 0.0,
                x: b.position(),
                u,
                q: b.rotation(),
                w,
                g,
            }
        })
        .collect();
    let search = |motion: &[Motion], p: &Pair, from: f64| {
        let reach = |k: usize| match world.bodies[k].shape {
            Shape::Box { .. } => world.bodies[k].bounding_radius(),
            _ => 0.0,
        };
        let (ma, mb) = (motion[p.a].at(from), motion[p.b].at(from));
        let shapes = (world.bodies[p.a].shape, world.bodies[p.b].shape);
        time_of_impact(&ma, &mb, shapes, (reach(p.a), reach(p.b)), dt, threshold)
    };
    for p in pairs.iter_mut() {
        p.toi = search(&motion, p, 0.0);
    }
    let mut hit = vec![false; world.bodies.len()];
    loop {
        let due = pairs
            .iter()
            .enumerate()
            .filter_map(|(i, p)| Some((p.toi?, i)));
        let Some((t, i)) = due.min_by(|x, y| x.0.total_cmp(&y.0)) else {
            break;
        };
        if out.count == MAX_IMPACTS {
            out.deferred = pairs.iter().filter(|p| p.toi.is_some()).count();
            break;
        }
        let (a, b) = (pairs[i].a, pairs[i].b);
        let (ma, mb) = (motion[a].at(t), motion[b].at(t));
        let Some((after, kicks)) =
            impact(world, [(a, &ma), (b, &mb)], moving, pairs[i].eps, threshold)
        else {
            pairs[i].toi = None;
            continue;
        };
        for (k, m, v) in [(a, ma, after[0]), (b, mb, after[1])] {
            if moving[k] {
                let (u, w) = (DVec3::from(v.velocity), DVec3::from(v.angular_velocity));
                motion[k] = Motion { u, w, ..m };
                hit[k] = true;
            }
        }
        if out.impulses.is_empty() {
            out.impulses = vec![0.0; contacts.len()];
        }
        let of_pair = |c: &&ContactPoint| (c.a, c.b) == (a, b);
        for (feature, z) in kicks {
            let same = contacts
                .iter()
                .position(|c| of_pair(&c) && c.feature == feature);
            if let Some(c) = same.or_else(|| contacts.iter().position(|c| of_pair(&c))) {
                out.impulses[c] += z;
            }
        }
        out.count += 1;
        if !out.struck.contains(&(a, b)) {
            out.struck.push((a, b));
        }
        for p in pairs.iter_mut() {
            if [p.a, p.b].iter().any(|&k| k == a || k == b) {
                p.toi = search(&motion, p, t);
            }
        }
    }
    for (k, _) in hit.iter().enumerate().filter(|(_, &h)| h) {
        let end = motion[k].at(dt);
        let vk = end.u - g * (0.5 * dt);
        v[k] = (vk, end.w);
        let q = integrate_rotation(end.q, -end.w, dt);
        out.starts.push((k, end.x - vk * dt, q));
    }
    out
}

/// The first time in [a.t, Δt] at which the pair touches while closing
/// (module docs); None when it does not within the step or cannot close
/// faster than `threshold` (`reach`: each body's radius for the closing
/// speed its spin adds, 0 where spin does not move its surface).
fn time_of_impact(
    a: &Motion,
    b: &Motion,
    shapes: (Shape, Shape),
    reach: (f64, f64),
    dt: f64,
    threshold: f64,
) -> Option<f64> {
    let g = a.g - b.g;
    let du = a.u - b.u;
    let spin = a.w.length() * reach.0 + b.w.length() * reach.1;
    // Against a plane only the normal parts close the gap; else all of it.
    let bound = match shapes.1 {
        Shape::Plane { normal } => {
            let n = DVec3::from(normal);
            (-n.dot(du)).max(0.0) + (-n.dot(g)).max(0.0) * (dt - a.t) + spin
        }
        _ => du.length() + g.length() * (dt - a.t) + spin,
    };
    if bound <= threshold {
        return None;
    }
    let tau = match shapes {
        (Shape::Sphere { radius }, Shape::Plane { normal }) if b.g == DVec3::ZERO => {
            let n = DVec3::from(normal);
            first_closing_root(n.dot(a.x - b.x) - radius, n.dot(du), 0.5 * n.dot(g))
        }
        (Shape::Sphere { radius: ra }, Shape::Sphere { radius: rb }) if g == DVec3::ZERO => {
            let d = a.x - b.x;
            let r = ra + rb;
            first_closing_root(
                d.length_squared() - r * r,
                2.0 * d.dot(du),
                du.length_squared(),
            )
        }
        _ => return advance(a, b, shapes, bound, dt),
    }?;
    let t = a.t + tau;
    (t <= dt).then_some(t)
}

/// The smallest τ ≥ 0 at which φ(τ) = c₀ + c₁τ + c₂τ² falls through 0
/// (φ' < 0 there); 0 when φ(0) ≤ 0 and it is falling.
fn first_closing_root(c0: f64, c1: f64, c2: f64) -> Option<f64> {
    if c0 <= 0.0 && c1 < 0.0 {
        return Some(0.0);
    }
    let falls = |t: f64| t >= 0.0 && c1 + 2.0 * c2 * t < 0.0;
    if c2 == 0.0 {
        return (c1 != 0.0).then(|| -c0 / c1).filter(|&t| falls(t));
    }
    let disc = c1 * c1 - 4.0 * c2 * c0;
    if disc < 0.0 {
        return None;
    }
    // The two roots without cancellation (Numerical Recipes §5.6).
    let k = -0.5 * (c1 + c1.signum() * disc.sqrt());
    let mut roots = [k / c2, if k != 0.0 { c0 / k } else { k / c2 }];
    roots.sort_by(f64::total_cmp);
    roots.into_iter().find(|&t| falls(t))
}

/// Conservative advancement: from a.t, steps of gap / `bound` (a bound on
/// the closing speed over the step) until the pair touches while closing.
/// Where it touches but separates there, the gap of the points closing now
/// is stepped on (none: no impact this step), so that a resting or sliding
/// pair is not stepped through in steps of [`TOUCH`].
fn advance(a: &Motion, b: &Motion, shapes: (Shape, Shape), bound: f64, dt: f64) -> Option<f64> {
    let mut t = a.t;
    for _ in 0..MAX_ADVANCES {
        let (x, y) = (a.at(t), b.at(t));
        let margin = bound * (dt - t) + TOUCH;
        let hits = collide_shapes(&x.placed(shapes.0), &y.placed(shapes.1), margin);
        // No point within reach: the pair cannot meet before the step ends.
        let mut gap = hits.iter().map(|h| h.gap).reduce(f64::min)?;
        if gap <= TOUCH {
            let closers = hits.iter().filter(|h| closing(&x, &y, h) < 0.0);
            let next = closers.map(|h| h.gap).reduce(f64::min)?;
            if next <= TOUCH {
                return Some(t);
            }
            // Touching where it separates (resting, sliding, just
            // bounced): only a point closing now is searched on.
            gap = next;
        }
        t += gap.max(TOUCH) / bound;
        if t > dt {
            return None;
        }
    }
    None
}

/// The impact of bodies a and b at their poses and velocities `m`: the
/// touching, closing points as one LCP with restitution `eps` and no gap
/// term. None when none closes faster than `threshold` or the LCP is not
/// solved. Gives both bodies' velocities after, and per point its
/// feature and impulse.
fn impact(
    world: &World,
    m: [(usize, &Motion); 2],
    moving: &[bool],
    eps: f64,
    threshold: f64,
) -> Option<([BodyVelocity; 2], Vec<(u16, f64)>)> {
    let [(a, ma), (b, mb)] = m;
    let shape = |k: usize| world.bodies[k].shape;
    let hits = collide_shapes(&ma.placed(shape(a)), &mb.placed(shape(b)), 2.0 * TOUCH);
    let touching: Vec<&Hit> = hits.iter().filter(|h| closing(ma, mb, h) < 0.0).collect();
    let fastest = touching
        .iter()
        .map(|h| -closing(ma, mb, h))
        .fold(0.0, f64::max);
    if fastest <= threshold {
        return None;
    }
    let body = |k: usize, m: &Motion| scene_body(&world.bodies[k], moving[k], m.x, m.q, (m.u, m.w));
    let scene = Scene {
        bodies: vec![body(a, ma), body(b, mb)],
        contacts: touching
            .iter()
            .map(|h| Contact {
                a: 0,
                b: Some(1),
                point: h.point.to_array(),
                normal: h.normal.to_array(),
                restitution: eps,
                id: None,
                bias: 0.0,
                friction: 0.0,
                tangent: None,
            })
            .collect(),
    };
    let built = Built::new(&scene);
    let mut z = vec![0.0; touching.len()];
    for (island, lcp) in built.islands.iter().zip(&built.lcps) {
        let solution = lemke(lcp, &LemkeSettings::default());
        if !solution.status.is_solution() {
            return None;
        }
        for (&c, &zc) in island.contacts.iter().zip(solution.z.iter()) {
            z[c] = zc;
        }
    }
    let after = apply_impulses(&scene, &built.rows, &z);
    let kicks = touching
        .iter()
        .zip(&z)
        .map(|(h, &zc)| (h.feature, zc))
        .collect();
    Some(([after[0], after[1]], kicks))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_closing_root_skips_the_root_a_bounce_leaves() {
        // Falling from 1 m at rest under g = 10: φ = 1 − 5τ², meets at √0.2.
        let t = first_closing_root(1.0, 0.0, -5.0).unwrap();
        assert!((t - 0.2f64.sqrt()).abs() < 1e-15, "{t}");
        // Just bounced (φ = 0, rising at 2 m/s): the next fall through 0 is
        // at τ = 0.4, not the root at 0.
        let t = first_closing_root(0.0, 2.0, -5.0).unwrap();
        assert!((t - 0.4).abs() < 1e-15, "{t}");
        // Touching and closing: now. Separating without gravity: never.
        assert_eq!(first_closing_root(0.0, -1.0, 0.0), Some(0.0));
        assert_eq!(first_closing_root(0.5, 1.0, 0.0), None);
        // Two spheres passing each other: |d + u τ|² − r² has no root.
        assert_eq!(first_closing_root(4.0 - 1.0, 0.0, 1.0), None);
    }
}
