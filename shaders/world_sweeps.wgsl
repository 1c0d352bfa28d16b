// The projected sweeps in the frictional phase of shaders/world_step.wgsl
// (module world_friction, composed after world_friction.wgsl, whose header
// gives the method, the layout of a world's region and the rounds): the
// method's part of `world_friction` for Jacobi and Gauss–Seidel
// (friction/projected.rs `sweeps`).

// One sweep of projected.rs `sweeps` (u from the iteration's start; for
// Gauss–Seidel each contact's rows again from the reactions so far).
fn sweep(base: u32, n: u32) {
    let dim = 3u * n;
    for (var i = 0u; i < n; i++) {
        let c = 3u * i;
        if sp.gauss_seidel != 0u {
            contact_velocity(base, dim, i, base + F_X, base + F_U);
        }
        let h = scratch[base + F_ETA + i];
        let x = vec3_x(base, i);
        let u = vec3_u(base, i);
        let p = project_on_cone(
            vec3<Scalar>(x.x - h * u.x, x.y - h * u.y, x.z - h * u.z),
            scratch[base + F_MU + i],
        );
        put_scratch(base + F_X + c, p);
    }
}

// Loop work of the method's start after an island's assembly: none (the
// sweeps start from x as assembled).
fn method_start_cost(n: u32) -> u32 {
    return 0u;
}

// The method's start after an island's assembly: nothing to do.
fn method_start(base: u32, n: u32) -> bool {
    return true;
}

// Iterations of `sweeps` within `sp.friction_budget` from `spent0`: u, the
// stop measure, a sweep, until the tolerance or the cap (ROUND_DONE), a
// non-finite measure (ROUND_NOT_FINITE) or the budget (ROUND_SPENT):
// (loop work spent, that).
fn method_round(base: u32, n: u32, q2: Scalar, fs: u32, spent0: u32) -> vec2<u32> {
    let cost = 2u * n * n + 8u * n + 16u;
    var spent = spent0;
    var end = ROUND_SPENT;
    loop {
        if spent + cost > sp.friction_budget {
            break;
        }
        spent += cost;
        let it = words[fs + 2u];
        friction_velocity(base, n, F_X, F_U);
        let err = stop_measure(base, n, q2, F_X, F_U);
        if !finite(err) {
            end = ROUND_NOT_FINITE;
            break;
        }
        if err <= sp.friction_tolerance || it >= sp.max_iterations {
            end = ROUND_DONE;
            break;
        }
        sweep(base, n);
        words[fs + 2u] = it + 1u;
    }
    return vec2<u32>(spent, end);
}
