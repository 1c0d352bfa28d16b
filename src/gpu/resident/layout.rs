//! The packed records of resident worlds (keep in sync with
//! `shaders/world_step.wgsl`'s header): what goes up once, what comes back
//! per step.

use crate::gpu::collide::shape_record;
use crate::world::{RigidBody, World};

/// Largest world (bodies) the kernel steps: its masks are one `u32`, its
/// per-body arrays private.
pub const MAX_BODIES: usize = 16;
/// Scalars per world in `consts`: gravity (3), margin, sleep linear, sleep
/// angular.
pub const WC: usize = 6;
/// Scalars per body in `consts`: kind, size (3), static flag, inverse mass,
/// body-frame inverse inertia (3), mass, bounding radius, friction
/// coefficient.
pub const BC: usize = 12;
/// Scalars per body in `state`: position (3), orientation `[x, y, z, w]`,
/// velocity (3), angular velocity (3).
pub const BS: usize = 13;
/// Scalars per contact slot in `scratch`: point (3), normal (3), gap, z.
pub const CP: usize = 8;
/// Scalars per contact slot's row in `scratch`, after the contact slots
/// (`world_assemble`): q, the response M⁻¹Jᵀ of sides a and b (12), the
/// contact's row of its island's M (16); the row's basic variable where
/// Lemke's path ended (`world_lemke`).
pub const ROW: usize = 30;
/// Scalars per world in `records`: kinetic, potential, max penetration,
/// max error, awake, friction rounds, and `world_solve_warm`'s warm-start
/// memory (a hash of last step's contact ids, the bases of its islands by
/// contact; read back with the rest, unused by the host).
pub const REC: usize = 8;
/// Scalars per world of the frictional phase's region in `scratch`
/// (`shaders/world_friction.wgsl`): an island's rows (48 × 24), W (48 × 48),
/// q, x, u and two temporaries (48 each), μ and η (16 each), APGD's y,
/// u(y), best iterate and its u (48 each), θ, L and the best error.
pub const FR: usize = 3923;

/// A world's flag bits (`words`, per world, third word).
pub mod flags {
    /// A pair gave more points than its slots or the world more contacts
    /// than [`super::contact_slots`].
    pub const CONTACTS_FULL: u32 = 1;
    /// An island of more than 16 contacts (Lemke's private tableau,
    /// `shaders/lemke.wgsl`).
    pub const ISLAND_TOO_LARGE: u32 = 2;
    /// Lemke gave up or its answer failed the door's check.
    pub const NOT_SOLVED: u32 = 4;
    /// A velocity or pose after the step is not finite.
    pub const NON_FINITE: u32 = 8;
    /// The loop budget of an invocation was spent, or llvmpipe's loop
    /// limit was met (`loops_left`).
    pub const BUDGET: u32 = 16;
    /// Handed by `world_solve_warm` to `world_friction` and kept until that
    /// finishes it: set after the step's last round, the rounds ran out
    /// for the world (counted as [`BUDGET`]).
    pub const HANDED: u32 = 32;
}

/// Why a world cannot be stepped by the resident kernel at all (None: it
/// can): restitution or more bodies than [`MAX_BODIES`].
pub fn out_of_scope(w: &World) -> Option<&'static str> {
    if w.bodies.len() > MAX_BODIES {
        return Some("more than 16 bodies");
    }
    if w.bodies.iter().any(|b| b.restitution != 0.0) {
        return Some("restitution");
    }
    None
}

/// Whether a contact of `w` may have friction: μ = √(μ_a μ_b) > 0 needs
/// two bodies with friction.
pub fn may_have_friction(w: &World) -> bool {
    w.bodies.iter().filter(|b| b.friction > 0.0).count() > 1
}

/// The id the shader packs for a contact from its id on the CPU
/// (`world::step::contact_id`: world, a, b, feature): (a << 16) | (b << 12)
/// | feature, the world left out (each world's memory is its own). Bodies
/// below [`MAX_BODIES`] keep a and b apart.
pub fn device_key(id: u64) -> u32 {
    let a = ((id >> 28) & 0xffff) as u32;
    let b = ((id >> 12) & 0xffff) as u32;
    (a << 16) | (b << 12) | (id & 0xfff) as u32
}

/// The CPU's contact id of world `world`'s contact with the shader's id
/// `key`: the inverse of [`device_key`].
pub fn cpu_id(world: usize, key: u32) -> u64 {
    let (a, b) = (u64::from(key >> 16), u64::from((key >> 12) & 0xf));
    ((world as u64 & 0xf_ffff) << 44) | (a << 28) | (b << 12) | u64::from(key & 0xfff)
}

/// Contact slots per world: 4 per pair that may touch (every pair type
/// gives at most 4 points), over the largest world of the batch; at least
/// 4. A world that would need more is flagged, never cut.
pub fn contact_slots(worlds: &[World]) -> usize {
    let pairs = |w: &World| {
        let n = w.bodies.len();
        let fixed = w.bodies.iter().filter(|b| b.fixed).count();
        n * (n.saturating_sub(1)) / 2 - fixed * fixed.saturating_sub(1) / 2
    };
    worlds
        .iter()
        .map(|w| 4 * pairs(w))
        .max()
        .unwrap_or(0)
        .max(4)
}

/// Appends body `b`'s constants (see [`BC`]).
pub fn pack_body_consts(b: &RigidBody, out: &mut Vec<f64>) {
    let (kind, size) = shape_record(&b.shape);
    let props = b.mass_properties();
    out.push(kind);
    out.extend_from_slice(&size);
    out.push(if b.fixed { 1.0 } else { 0.0 });
    out.push(props.inv_mass);
    out.extend_from_slice(&props.inv_inertia.to_array());
    out.push(if b.fixed { 0.0 } else { b.mass() });
    out.push(if b.fixed { 0.0 } else { b.bounding_radius() });
    out.push(b.friction);
}

/// Appends world `w`'s constants (see [`WC`]).
pub fn pack_world_consts(w: &World, out: &mut Vec<f64>) {
    out.extend_from_slice(&w.gravity);
    out.push(w.contact_margin);
    out.push(w.sleep.linear);
    out.push(w.sleep.angular);
}

/// Appends body `b`'s state (see [`BS`]) to `state` and its sleep words
/// (asleep, quiet steps) to `words`.
pub fn pack_body_state(b: &RigidBody, state: &mut Vec<f64>, words: &mut Vec<u32>) {
    state.extend_from_slice(&b.position);
    state.extend_from_slice(&b.orientation);
    state.extend_from_slice(&b.velocity);
    state.extend_from_slice(&b.angular_velocity);
    words.extend_from_slice(&[u32::from(b.asleep), b.quiet_steps]);
}

/// Body `b`'s state from its record (`state`, [`BS`] scalars) and sleep
/// words (`sleep`, 2): the inverse of [`pack_body_state`], bit for bit.
pub fn unpack_body_state(b: &mut RigidBody, state: &[f64], sleep: &[u32]) {
    b.position.copy_from_slice(&state[0..3]);
    b.orientation.copy_from_slice(&state[3..7]);
    b.velocity.copy_from_slice(&state[7..10]);
    b.angular_velocity.copy_from_slice(&state[10..13]);
    b.asleep = sleep[0] != 0;
    b.quiet_steps = sleep[1];
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::world::generate::{standard_world, WorldKind};

    #[test]
    fn a_body_state_comes_back_bit_for_bit() {
        let w = standard_world(WorldKind::Rain, 8, 3);
        for b in &w.bodies {
            let (mut s, mut words) = (Vec::new(), Vec::new());
            pack_body_state(b, &mut s, &mut words);
            assert_eq!((s.len(), words.len()), (BS, 2));
            let mut back = b.clone();
            back.position = [0.0; 3];
            back.quiet_steps = 7;
            unpack_body_state(&mut back, &s, &words);
            assert_eq!(&back, b);
        }
    }

    /// The shader's constants are these.
    #[test]
    fn the_shader_has_these_layouts() {
        let src = include_str!("../../../shaders/world_step.wgsl");
        for (name, v) in [
            ("MAX_BODIES", MAX_BODIES),
            ("WC", WC),
            ("BC", BC),
            ("BS", BS),
        ]
        .into_iter()
        .chain([("CP", CP), ("ROW", ROW), ("REC", REC)])
        {
            assert!(
                src.contains(&format!("const {name}: u32 = {v}u;")),
                "{name}"
            );
        }
        let friction = include_str!("../../../shaders/world_friction.wgsl");
        assert!(friction.contains(&format!("const FR: u32 = {FR}u;")));
        for (name, v) in [
            ("CONTACTS_FULL", flags::CONTACTS_FULL),
            ("ISLAND_TOO_LARGE", flags::ISLAND_TOO_LARGE),
            ("NOT_SOLVED", flags::NOT_SOLVED),
            ("NON_FINITE", flags::NON_FINITE),
            ("BUDGET", flags::BUDGET),
            ("HANDED", flags::HANDED),
        ] {
            assert!(
                src.contains(&format!("const {name}: u32 = {v}u;")),
                "{name}"
            );
        }
    }

    #[test]
    fn contact_ids_go_to_the_device_and_back() {
        use crate::world::collide::ContactPoint;
        use crate::world::step::contact_id;
        for (world, a, b, feature) in [(0, 1, 0, 0), (7, 15, 14, 0xfff), (1 << 19, 3, 9, 0x123)] {
            let p = ContactPoint {
                a,
                b,
                point: glam::DVec3::ZERO,
                normal: glam::DVec3::Z,
                gap: 0.0,
                feature,
            };
            let id = contact_id(world, &p);
            assert_eq!(cpu_id(world, device_key(id)), id);
        }
    }

    #[test]
    fn slots_cover_four_points_per_pair_that_may_touch() {
        let w = standard_world(WorldKind::Stack, 4, 1);
        // 4 boxes and the ground: 10 pairs.
        assert_eq!(contact_slots(std::slice::from_ref(&w)), 40);
        assert_eq!(contact_slots(&[]), 4);
        assert!(contact_slots(&[w]) <= 4 * MAX_BODIES * (MAX_BODIES - 1) / 2);
    }
}
