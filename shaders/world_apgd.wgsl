// APGD in the frictional phase of shaders/world_step.wgsl (module
// world_friction_apgd, composed after world_friction.wgsl, whose header
// gives the method, the layout of a world's region and the rounds;
// `world_friction` calls method_start (apgd_start) after an island's
// assembly and method_round (apgd_round) in each round): the twin of
// friction/apgd.rs, its arithmetic in its order, on the island's W, q and
// μ in `scratch`. accept_step and apgd_momentum are friction_common.wgsl's
// (the batch APGD kernels' own).

// Copies contact after contact 3n entries from base + `src` to base + `dst`.
fn copy_entries(base: u32, n: u32, src: u32, dst: u32) {
    for (var i = 0u; i < n; i++) {
        put_scratch(base + dst + 3u * i, vec3_at_scratch(base + src + 3u * i));
    }
}

// apgd.rs first_lipschitz: ‖W e‖ / ‖e‖ for e = (1, …, 1), else the largest
// |W_rr|, else 1.
fn first_lipschitz(base: u32, n: u32) -> Scalar {
    let dim = 3u * n;
    var s2 = Scalar(0.0);
    for (var r = 0u; r < dim; r++) {
        let row = base + F_W + r * dim;
        var s = Scalar(0.0);
        for (var j = 0u; j < dim; j += 3u) {
            s += scratch[row + j];
            s += scratch[row + j + 1u];
            s += scratch[row + j + 2u];
        }
        s2 += s * s;
    }
    let l = sqrt(s2 / Scalar(dim));
    if l > Scalar(0.0) && finite(l) {
        return l;
    }
    var d = Scalar(0.0);
    for (var r = 0u; r < dim; r++) {
        d = max(d, abs(scratch[base + F_W + r * dim + r]));
    }
    return select(Scalar(1.0), d, d > Scalar(0.0) && finite(d));
}

// APGD's start (apgd.rs apgd) from x (projected by assemble_friction):
// u(x), its error, y = x, u(y) = u(x), best = x, θ = 1, L; false where
// the error is not finite (the twin fails).
fn apgd_start(base: u32, n: u32, q2: Scalar) -> bool {
    friction_velocity(base, n, F_X, F_U);
    let err = stop_measure(base, n, q2, F_X, F_U);
    copy_entries(base, n, F_X, F_Y);
    copy_entries(base, n, F_U, F_UY);
    copy_entries(base, n, F_X, F_BEST);
    copy_entries(base, n, F_U, F_UBEST);
    let a = base + F_APGD;
    scratch[a] = Scalar(1.0);
    scratch[a + 1u] = first_lipschitz(base, n);
    scratch[a + 2u] = err;
    return finite(err);
}

// One backtracking try from y with step 1/L (apgd_iteration): the trial
// xn = P_K(y − u(y) / L) into T1, u(xn) into T2; whether accept_step takes
// it (d = xn − y, W d = u(xn) − u(y)).
fn apgd_try(base: u32, n: u32, lipschitz: Scalar) -> bool {
    let t = Scalar(1.0) / lipschitz;
    for (var i = 0u; i < n; i++) {
        let y = vec3_at_scratch(base + F_Y + 3u * i);
        let uy = vec3_at_scratch(base + F_UY + 3u * i);
        put_scratch(base + F_T1 + 3u * i, project_on_cone(y - t * uy, scratch[base + F_MU + i]));
    }
    friction_velocity(base, n, F_T1, F_T2);
    var curvature = Scalar(0.0);
    var d2 = Scalar(0.0);
    var g2 = Scalar(0.0);
    for (var i = 0u; i < n; i++) {
        let d = vec3_at_scratch(base + F_T1 + 3u * i) - vec3_at_scratch(base + F_Y + 3u * i);
        let uy = vec3_at_scratch(base + F_UY + 3u * i);
        let wd = vec3_at_scratch(base + F_T2 + 3u * i) - uy;
        curvature += d.x * wd.x;
        curvature += d.y * wd.y;
        curvature += d.z * wd.z;
        d2 += d.x * d.x;
        d2 += d.y * d.y;
        d2 += d.z * d.z;
        g2 += uy.x * uy.x;
        g2 += uy.y * uy.y;
        g2 += uy.z * uy.z;
    }
    return accept_step(curvature, d2, g2, lipschitz);
}

// After an accepted try (apgd_iteration): the best iterate (with its u),
// the momentum, the gradient restart, x = xn, L × 0.9, the iteration
// counted in words[fs + 2]; false where the trial's error is not finite.
fn apgd_accept(base: u32, n: u32, q2: Scalar, fs: u32) -> bool {
    let err = stop_measure(base, n, q2, F_T1, F_T2);
    if !finite(err) {
        return false;
    }
    let a = base + F_APGD;
    if err < scratch[a + 2u] {
        scratch[a + 2u] = err;
        copy_entries(base, n, F_T1, F_BEST);
        copy_entries(base, n, F_T2, F_UBEST);
    }
    let m = apgd_momentum(scratch[a]);
    var g_dot = Scalar(0.0);
    for (var i = 0u; i < n; i++) {
        let d = vec3_at_scratch(base + F_T1 + 3u * i) - vec3_x(base, i);
        let uy = vec3_at_scratch(base + F_UY + 3u * i);
        g_dot += uy.x * d.x;
        g_dot += uy.y * d.y;
        g_dot += uy.z * d.z;
    }
    let restart = g_dot > Scalar(0.0);
    for (var i = 0u; i < n; i++) {
        let xn = vec3_at_scratch(base + F_T1 + 3u * i);
        let un = vec3_at_scratch(base + F_T2 + 3u * i);
        var y = xn;
        var uy = un;
        if !restart {
            y = xn + m.y * (xn - vec3_x(base, i));
            uy = un + m.y * (un - vec3_u(base, i));
        }
        put_scratch(base + F_Y + 3u * i, y);
        put_scratch(base + F_UY + 3u * i, uy);
        put_scratch(base + F_X + 3u * i, xn);
        put_scratch(base + F_U + 3u * i, un);
    }
    scratch[a] = select(m.x, Scalar(1.0), restart);
    scratch[a + 1u] = scratch[a + 1u] * Scalar(0.9);
    words[fs + 2u] += 1u;
    words[fs + 3u] = 0u;
    return true;
}

// The APGD iterations of a round within `budget` from `spent` (the twin's
// loop: stop at the tolerance or the cap, else a try, doubling L where it
// fails): (loop work spent, ROUND_DONE or ROUND_FAILED; ROUND_SPENT where
// the budget ends it first), the best iterate and its u
// in x and u where done.
fn apgd_round(base: u32, n: u32, q2: Scalar, fs: u32, spent0: u32) -> vec2<u32> {
    let cost = n * n + 10u * n + 16u;
    let a = base + F_APGD;
    var spent = spent0;
    var end = ROUND_SPENT;
    loop {
        if scratch[a + 2u] <= sp.friction_tolerance || words[fs + 2u] >= sp.max_iterations {
            copy_entries(base, n, F_BEST, F_X);
            copy_entries(base, n, F_UBEST, F_U);
            spent += 2u * n;
            end = ROUND_DONE;
            break;
        }
        if spent + cost > sp.friction_budget {
            break;
        }
        spent += cost;
        let l = scratch[a + 1u];
        if apgd_try(base, n, l) {
            if !apgd_accept(base, n, q2, fs) {
                end = ROUND_FAILED;
                break;
            }
        } else {
            scratch[a + 1u] = Scalar(2.0) * l;
            words[fs + 3u] += 1u;
            if words[fs + 3u] >= MAX_BACKTRACKS || !finite(scratch[a + 1u]) {
                end = ROUND_FAILED;
                break;
            }
        }
    }
    return vec2<u32>(spent, end);
}

// Loop work of APGD's start after an island's assembly.
fn method_start_cost(n: u32) -> u32 {
    return 4u * n * n + 16u * n + 16u;
}

// APGD's start after an island's assembly (apgd_start).
fn method_start(base: u32, n: u32) -> bool {
    return apgd_start(base, n, sum_squares_at(base + F_Q, 3u * n));
}

// APGD's iterations of a round (apgd_round).
fn method_round(base: u32, n: u32, q2: Scalar, fs: u32, spent0: u32) -> vec2<u32> {
    return apgd_round(base, n, q2, fs, spent0);
}
