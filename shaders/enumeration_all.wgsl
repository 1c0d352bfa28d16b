// Every basis of every island (--all-solutions on the GPU): one invocation
// per (island, basis) pair. Each solves its basis by the shared elimination
// (shaders/enumeration_basis.wgsl, prepended by the generator) and records
// a verdict of two bits in `verdicts`; the CPU re-solves the flagged bases
// in f64 and decides the solution set exactly as its own enumeration does
// (src/gpu/all_bases.rs; CPU twin: src/cpu/enumeration.rs, `enumerate`).
//
// One dispatch covers islands of one size n: invocation t of the dispatch
// range is basis (t mod 2^n) of island params.budget + t / 2^n (Params'
// `budget` carries the first island of the size group, `flags` carries n;
// `first`/`count` the range of t). Island.z is, in this kernel, the island's
// first word in `verdicts` (2^n / 16 words, at least one).
//
// Verdict bits of basis m at word z + m / 16, bits 2 (m mod 16) + {0, 1}:
// CANDIDATE when its infeasibility is at most max(tol.relaxed, tol.screen)
// (every basis the CPU could count as a solution, with the f32 slack of the
// screen tolerance), SINGULAR_BASIS when the elimination met a pivot below
// tol.pivot. In f64 the arithmetic is the CPU twin's, so the host trusts
// SINGULAR_BASIS; in f32 it re-solves those too.

@group(0) @binding(8) var<storage, read_write> verdicts: array<atomic<u32>>;

const CANDIDATE: u32 = 1u;
const SINGULAR_BASIS: u32 = 2u;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    if gid.x >= params.count {
        return;
    }
    let n = params.flags;
    let t = params.first + gid.x;
    let island = islands[params.budget + (t >> n)];
    let mask = t & ((1u << n) - 1u);
    let r = solve_basis(island.data, n, mask);
    var v = 0u;
    if r == SINGULAR {
        v = SINGULAR_BASIS;
    } else if r <= max(tol.relaxed, tol.screen) {
        v = CANDIDATE;
    }
    if v != 0u {
        atomicOr(&verdicts[island.z + mask / 16u], v << (2u * (mask % 16u)));
    }
}
