//! The faceted start and its polish: the faceted LCP's answer checked
//! against the pyramid model it solves (seeded random islands), the
//! polish checked by the Coulomb error it reports (never against stored
//! answers), and two islands `rain:32` left unsolved before this step
//! (dumped from `lcpbatch simulate --world rain:32 --worlds 4 --steps
//! 1000`, solved cold at the CLI's tolerance 1e-12).

use super::*;
use crate::friction::random::random_problem;
use crate::friction::residual::{coulomb_error, FrictionResiduals};
use crate::friction::{solve_friction_problem, FrictionMethod, FrictionSettings};
use crate::generate::Rng;

/// The islands: a box on four corners whose answer lifts one corner at
/// 7.8e-11 m/s and slides two at 4e-11–6e-11 m/s (W of rank 6, q outside
/// W's range by 1.9e-10 of ‖q‖), and a 4-contact pile that slides.
fn dumped() -> [FrictionProblem; 2] {
    [U5, U6].map(|(w, q, mu)| FrictionProblem::new(w.to_vec(), q.to_vec(), mu.to_vec()).unwrap())
}

#[test]
fn the_faceted_answer_solves_the_pyramid_model_in_the_round_cones() {
    let mut rng = Rng::new(24);
    for k in 1..=FACETED_MAX {
        for _ in 0..4 {
            let p = random_problem(&mut rng, k, 100.0);
            let (mut r, mut slide) = (vec![0.0; p.dim()], vec![0.0; k]);
            let (pivots, found) = faceted_start(&p, &mut r, &mut slide, 10_000);
            assert!(found, "k = {k}: no answer after {pivots} pivots");
            let u = p.velocity(&r);
            let scale = 1.0 + r.iter().chain(&u).fold(0.0f64, |m, v| m.max(v.abs()));
            let res = FrictionResiduals::of_velocity(&p, &r, &u);
            // In the round cones; normal complementarity exact to rounding.
            assert!(res.cone_violation <= 1e-12 * scale, "k = {k}: {res:?}");
            for i in 0..k {
                let (rn, un) = (r[3 * i], u[3 * i]);
                assert!(
                    rn >= 0.0 && un >= -1e-10 * scale,
                    "k = {k}, contact {i}: r_n {rn}, u_n {un}"
                );
                assert!(
                    (rn * un).abs() <= 1e-10 * scale * scale,
                    "k = {k}, contact {i}"
                );
                // A sticking contact (λ = 0) does not move; a sliding one
                // moves against its friction, at most λ fast along any face
                // direction's opposite.
                let ut = [u[3 * i + 1], u[3 * i + 2]];
                if slide[i] == 0.0 && rn > 0.0 {
                    assert!(
                        ut[0].hypot(ut[1]) <= 1e-9 * scale,
                        "k = {k}, contact {i}: {ut:?}"
                    );
                }
                assert!(ut[0] * r[3 * i + 1] + ut[1] * r[3 * i + 2] <= 1e-9 * scale * scale);
            }
        }
    }
}

#[test]
fn the_polish_reports_only_answers_within_the_tolerance() {
    // Random islands (mass ratios to 1e3, singular W from 2 contacts per
    // body on): whatever the polish accepts is a Coulomb answer, judged
    // afresh; most are accepted.
    let mut rng = Rng::new(7);
    let (mut tried, mut accepted) = (0, 0);
    for k in 2..=8 {
        for _ in 0..10 {
            let p = random_problem(&mut rng, k, 1e3);
            let (mut r, mut slide) = (vec![0.0; p.dim()], vec![0.0; k]);
            assert!(faceted_start(&p, &mut r, &mut slide, 10_000).1, "k = {k}");
            let faceted = r.clone();
            let (steps, e) = polish(&p, &mut r, &slide, 1000, 1e-12);
            assert!(steps <= 1000);
            tried += 1;
            if e <= 1e-12 {
                accepted += 1;
                let fresh = coulomb_error(&p, &r);
                assert!(fresh <= 1e-12, "k = {k}: reported {e:e}, is {fresh:e}");
            } else {
                assert_eq!(r, faceted, "k = {k}: a rejected polish left r changed");
            }
        }
    }
    assert!(2 * accepted >= tried, "{accepted} of {tried} accepted");
}

#[test]
fn islands_that_stalled_every_method_are_settled_within_the_cap() {
    let s = FrictionSettings {
        method: FrictionMethod::Auto,
        tolerance: 1e-12,
        max_iterations: 1000,
    };
    for (which, p) in dumped().iter().enumerate() {
        let sol = solve_friction_problem(p, None, &s);
        assert_eq!(
            sol.status,
            crate::lcp::Status::Solved,
            "island {which}: {:?}",
            sol.residuals
        );
        assert!(
            sol.residuals.coulomb_error <= 1e-12 && sol.iterations < 200,
            "island {which}: {} iterations",
            sol.iterations
        );
        assert!(coulomb_error(p, &sol.r) <= 1e-12);
    }
    // The box: one corner lifts (r = 0, u_n > 0).
    let p = &dumped()[0];
    let sol = solve_friction_problem(p, None, &s);
    assert!(
        (0..4).any(|i| sol.r[3 * i] == 0.0 && sol.u[3 * i] > 0.0),
        "{:?}",
        sol.r
    );
}

/// `u5`: W (row-major), q, μ.
const U5: ([f64; 144], [f64; 12], [f64; 4]) = (
    [
        0.020910618011768814,
        -0.00857685847404166,
        0.0033101553397242877,
        0.001380385393428902,
        -0.008576858474812892,
        0.0033101553412216113,
        0.007721878811503505,
        -0.008576858435751337,
        0.0033101553257566477,
        -0.01180835380683638,
        -0.008576858436522571,
        0.003310155327253971,
        -0.00857685847404166,
        0.009171084893595133,
        -0.0001922019448652992,
        0.002422339106904128,
        0.010008701190067575,
        -0.0018497020087757216,
        -0.0024223390781993766,
        0.008160185695827613,
        -0.0007030590089457676,
        0.008576858502746396,
        0.008997801992300054,
        -0.002360559072856188,
        0.0033101553397242877,
        -0.0001922019448652992,
        0.02453192029237796,
        0.008868590808630963,
        0.010289221851681045,
        0.0037909668439124397,
        -0.008868590865455713,
        -0.012841982924993322,
        0.018139363828967654,
        -0.0033101553965490366,
        -0.002360559128446983,
        -0.002601589619497845,
        0.0013803853934289036,
        0.002422339106904127,
        0.008868590808630965,
        0.020910618011736,
        0.002422339107673765,
        0.008868590807136796,
        -0.01180835380683638,
        0.002422339095423913,
        0.008868590769511825,
        0.0077218788114707055,
        0.002422339096193552,
        0.008868590768017656,
        -0.008576858474812892,
        0.010008701190067575,
        0.010289221851681045,
        0.002422339107673766,
        0.018944071547195365,
        -0.007392355023681583,
        -0.0024223390789690153,
        -0.0007751847060344123,
        0.004839593983368721,
        0.008576858503517628,
        0.008160185651093372,
        -0.012841982891993887,
        0.0033101553412216113,
        -0.0018497020087757218,
        0.0037909668439124397,
        0.008868590807136792,
        -0.007392355023681583,
        0.01475893363876435,
        -0.008868590863961542,
        0.004839594038923201,
        0.0071713970788366225,
        -0.00331015539804636,
        -0.0007030589759826583,
        0.018139363873688523,
        0.007721878811503504,
        -0.0024223390781993757,
        -0.008868590865455713,
        -0.011808353806836376,
        -0.002422339078969014,
        -0.008868590863961542,
        0.02091061813483322,
        -0.0024223390667191627,
        -0.008868590826336575,
        0.001380385516493353,
        -0.002422339067488802,
        -0.008868590824842404,
        -0.00857685843575134,
        0.008160185695827613,
        -0.01284198292499332,
        0.002422339095423914,
        -0.0007751847060344132,
        0.004839594038923201,
        -0.002422339066719163,
        0.018944071606425403,
        -0.007392355018260246,
        0.008576858464456076,
        0.010008701204563385,
        0.010289221945656254,
        0.0033101553257566477,
        -0.0007030590089457678,
        0.01813936382896765,
        0.008868590769511825,
        0.00483959398336872,
        0.007171397078836624,
        -0.008868590826336575,
        -0.007392355018260246,
        0.014758933551908694,
        -0.003310155382581396,
        -0.0018497020259457607,
        0.0037909668017776788,
        -0.01180835380683638,
        0.008576858502746398,
        -0.003310155396549036,
        0.007721878811470708,
        0.008576858503517628,
        -0.0033101553980463597,
        0.0013803855164933538,
        0.008576858464456076,
        -0.003310155382581396,
        0.020910618134800413,
        0.008576858465227308,
        -0.0033101553840787197,
        -0.008576858436522571,
        0.008997801992300054,
        -0.0023605591284469826,
        0.0024223390961935526,
        0.00816018565109337,
        -0.0007030589759826579,
        -0.002422339067488802,
        0.010008701204563385,
        -0.0018497020259457607,
        0.008576858465227308,
        0.009171084863356703,
        -0.0001922018734814377,
        0.0033101553272539713,
        -0.0023605590728561885,
        -0.002601589619497845,
        0.008868590768017654,
        -0.012841982891993887,
        0.01813936387368852,
        -0.008868590824842404,
        0.010289221945656254,
        0.0037909668017776788,
        -0.0033101553840787197,
        -0.00019220187348143835,
        0.02453192029496402,
    ],
    [
        -0.25912993633530085,
        0.01763727719427131,
        -0.03490110380653331,
        -0.25912993662235667,
        0.017637239399730997,
        -0.03490102901757177,
        -0.09784815688107835,
        0.017637322673382604,
        -0.0349010804900801,
        -0.09784815724574553,
        0.01763728487884229,
        -0.034901005701118565,
    ],
    [0.4, 0.4, 0.4, 0.4],
);

/// `u6`: W (row-major), q, μ.
const U6: ([f64; 144], [f64; 12], [f64; 4]) = (
    [
        0.046386748197453365,
        0.014677061039172289,
        0.007399021519829277,
        0.00817141592386806,
        0.014715810836596522,
        0.007386759922170485,
        0.009240390694874426,
        0.014752756231676553,
        0.007406193186858728,
        -0.028974941578710868,
        0.014791506029100784,
        0.007393931589199936,
        0.014677061039172289,
        0.022168802987304642,
        -0.011205404222076838,
        0.007787788808006217,
        0.004720468950523401,
        -0.005684229110550253,
        -0.007734207406925608,
        0.027434440059228543,
        0.005295365895336439,
        -0.014623479638091663,
        0.009986106022447289,
        0.010816541006863009,
        0.007399021519829276,
        -0.011205404222076838,
        0.035552541549588035,
        -0.014507572376837415,
        0.020346282564480792,
        0.025568643518030478,
        0.014490617616434073,
        -0.020648663099911316,
        0.005753713144312915,
        -0.007415976280232634,
        0.010903023686646342,
        -0.004230184887244616,
        0.008171415923868061,
        0.007787788808006216,
        -0.014507572376837412,
        0.04638674820197667,
        0.007749039009374453,
        -0.01449531077879652,
        -0.028974941578691425,
        0.007845579661936691,
        -0.014556983026762615,
        0.009240390699417232,
        0.007806829863304928,
        -0.014544721428721721,
        0.01471581083659652,
        0.0047204689505234015,
        0.02034628256448079,
        0.007749039009374453,
        0.03714312183968628,
        0.01008678479111878,
        -0.007695457608301319,
        -0.0049384627806007214,
        -0.010318425056760519,
        -0.014662229435523371,
        0.027484190108562186,
        -0.0205779228301225,
        0.007386759922170485,
        -0.005684229110550254,
        0.025568643518030478,
        -0.014495310778796523,
        0.01008678479111878,
        0.020578222697374207,
        0.014478356018395547,
        -0.010404907731881234,
        0.010694383915817517,
        -0.007403714682571476,
        0.005366106169787815,
        0.005703963095161264,
        0.009240390694874425,
        -0.007734207406925608,
        0.014490617616434075,
        -0.02897494157869143,
        -0.007695457608301319,
        0.014478356018395547,
        0.04620955102863528,
        -0.007791679880387395,
        0.014539927521240042,
        0.007994218755069381,
        -0.007752930081763105,
        0.014527665923201516,
        0.014752756231676552,
        0.027434440059228543,
        -0.020648663099911313,
        0.007845579661936693,
        -0.0049384627806007214,
        -0.010404907731881232,
        -0.007791679880387395,
        0.03716671800555799,
        0.009967009648694163,
        -0.014698856450127237,
        0.004793815165728697,
        0.020210765016724218,
        0.007406193186858728,
        0.0052953658953364385,
        0.005753713144312915,
        -0.014556983026762615,
        -0.010318425056760519,
        0.010694383915817517,
        0.014539927521240042,
        0.009967009648694162,
        0.02056187226280909,
        -0.007423248692381318,
        -0.005646781303402809,
        0.025502543034313676,
        -0.028974941578710865,
        -0.014623479638091661,
        -0.007415976280232635,
        0.009240390699417237,
        -0.014662229435523368,
        -0.007403714682571476,
        0.00799421875506938,
        -0.014698856450127236,
        -0.007423248692381319,
        0.04620955103319746,
        -0.01473760624755894,
        -0.0074109870947201605,
        0.014791506029100782,
        0.009986106022447289,
        0.01090302368664634,
        0.007806829863304929,
        0.02748419010856219,
        0.005366106169787814,
        -0.007752930081763106,
        0.004793815165728697,
        -0.005646781303402809,
        -0.014737606247558944,
        0.02229189925184361,
        -0.011183698820261321,
        0.007393931589199936,
        0.010816541006863009,
        -0.0042301848872446125,
        -0.014544721428721723,
        -0.0205779228301225,
        0.005703963095161264,
        0.014527665923201516,
        0.020210765016724214,
        0.02550254303431368,
        -0.0074109870947201605,
        -0.011183698820261321,
        0.035436691016719535,
    ],
    [
        -0.44703029929642946,
        -0.08756556750576236,
        0.02771574695507368,
        -0.4470302941242329,
        -0.08756780629552736,
        0.027716455375161538,
        -0.09757650379614577,
        -0.08801904968598635,
        0.02786157164088583,
        -0.0975764941648333,
        -0.08802128847575136,
        0.027862280060973684,
    ],
    [0.4, 0.4, 0.4, 0.4],
);

/// Islands of `rain:32` (`lcpbatch simulate --world rain:32 --worlds 4
/// --steps 1000 --threads 1`) that `auto` left unsolved at the cap of
/// 1,000 with the faceted round's first active sets alone (dumped at the
/// solve with their warm starts, every f64 as its 16 hex digits so that
/// the bits are the world's): boxes on four corners and small piles, 4–13
/// contacts, whose answer lies in a neighbour of the best faceted set
/// (`faceted_islands.json`; W row-major, q, μ, the warm start or null).
fn rain_islands() -> Vec<(FrictionProblem, Option<Vec<f64>>)> {
    islands_of(include_str!("faceted_islands.json"))
}

/// The islands of a dump in `faceted_islands.json`'s format.
fn islands_of(text: &str) -> Vec<(FrictionProblem, Option<Vec<f64>>)> {
    let file: serde_json::Value = serde_json::from_str(text).unwrap();
    let numbers = |v: &serde_json::Value| -> Vec<f64> {
        let hex = v.as_str().unwrap();
        (0..hex.len() / 16)
            .map(|i| f64::from_bits(u64::from_str_radix(&hex[16 * i..16 * i + 16], 16).unwrap()))
            .collect()
    };
    file["islands"]
        .as_array()
        .unwrap()
        .iter()
        .map(|island| {
            let p = FrictionProblem::new(
                numbers(&island["W"]),
                numbers(&island["q"]),
                numbers(&island["mu"]),
            )
            .unwrap();
            let start = (!island["start"].is_null()).then(|| numbers(&island["start"]));
            (p, start)
        })
        .collect()
}

#[test]
fn rain_islands_left_unsolved_by_the_faceted_sets_are_solved_by_auto() {
    let islands = rain_islands();
    assert_eq!(islands.len(), 8);
    solved_warm_and_cold(&islands);
}

/// Islands of `rain:32` that `auto` left unsolved at the cap of 1,000
/// with PROX run from the start after the faceted round (dumped at the
/// solve with their warm starts, bits exact, as `faceted_islands.json`:
/// from `lcpbatch simulate --world rain:32 --threads 2`, 4 worlds × 1,000
/// steps and 100 worlds × 300 steps, seeds 1 and 501; boxes on four
/// corners and piles of 4–15 contacts, the faceted round's polish short
/// by 1e-12–1e-10): PROX from the polished r solves them, from the start
/// it runs out of steps.
#[test]
fn rain_islands_left_to_prox_from_the_start_are_solved_by_auto() {
    let islands = islands_of(include_str!("prox_islands.json"));
    assert_eq!(islands.len(), 8);
    solved_warm_and_cold(&islands);
}

/// Each island solved by `auto` at the CLI's tolerance 1e-12 and the cap
/// of 1,000, from its warm start and from zero, its Coulomb error
/// recomputed from the returned r.
fn solved_warm_and_cold(islands: &[(FrictionProblem, Option<Vec<f64>>)]) {
    let s = FrictionSettings {
        method: FrictionMethod::Auto,
        tolerance: 1e-12,
        max_iterations: 1000,
    };
    for (which, (p, start)) in islands.iter().enumerate() {
        // As the world solves it (warm), and from zero.
        for from in [start.as_deref(), None] {
            let sol = solve_friction_problem(p, from, &s);
            let fresh = coulomb_error(p, &sol.r);
            assert!(
                sol.status == crate::lcp::Status::Solved && fresh <= 1e-12,
                "island {which} ({} contacts, warm {}): {:?} after {} iterations, error {fresh:e}",
                p.contacts(),
                from.is_some(),
                sol.status,
                sol.iterations
            );
        }
    }
}
