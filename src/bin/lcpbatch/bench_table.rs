//! `lcpbatch bench`'s output: the family table as printed, and `bench.json`
//! (the rows and the curves).

use std::path::Path;

use serde::Serialize;

use lcpbatch::io::write_atomically;
use lcpbatch::Error;

use crate::bench::BenchRow;
use crate::plots::Curve;

/// One row of the family table.
pub fn row_line(r: &BenchRow) -> String {
    let st: Vec<String> = r.statuses.iter().map(|(k, v)| format!("{k}={v}")).collect();
    format!(
        "{:<17} {:<28} {:<7} {:>8} {:>12.0} {:>10.1e} {:>10.1e}  {} {}",
        r.family,
        r.solver,
        r.backend,
        r.islands,
        r.islands_per_second,
        r.median_error,
        r.max_error,
        st.join(" "),
        r.note
    )
}

/// Prints the table: the rows, then the GPU rows' phases.
pub fn print_table(rows: &[BenchRow]) {
    println!(
        "{:<17} {:<28} {:<7} {:>8} {:>12} {:>10} {:>10}  statuses / notes",
        "family", "solver", "backend", "islands", "islands/s", "median err", "max err"
    );
    for r in rows {
        println!("{}", row_line(r));
    }
    let gpu_rows: Vec<&BenchRow> = rows
        .iter()
        .filter(|r| !r.phases_us_per_island.is_empty())
        .collect();
    if !gpu_rows.is_empty() {
        println!(
            "\nGPU rows, µs per island by phase (host side, adding up to the call; kernels: \
             the host's wait for them), then the kernels by the device's timestamps and the \
             host work overlapped with them:"
        );
    }
    for r in gpu_rows {
        let phases: Vec<String> = r
            .phases_us_per_island
            .iter()
            .map(|(name, us)| format!("{name} {us:.2}"))
            .collect();
        let device = r
            .device_kernels_us_per_island
            .map_or("none".to_string(), |us| format!("{us:.2}"));
        println!(
            "{:<17} {:<28} {}; device kernels {device}, overlapped {:.2}",
            r.family,
            r.solver,
            phases.join(", "),
            r.overlapped_us_per_island
        );
    }
}

/// Writes the rows and the curves (seconds per island) as JSON, atomically.
pub fn write_json(
    rows: &[BenchRow],
    curves: &[(&str, &[Curve])],
    machine: &str,
    path: &Path,
) -> Result<(), Error> {
    #[derive(Serialize)]
    struct CurveOut<'a> {
        plot: &'a str,
        label: &'a str,
        /// (x, seconds per island)
        points: &'a [(f64, f64)],
    }
    #[derive(Serialize)]
    struct File<'a> {
        machine: &'a str,
        rows: &'a [BenchRow],
        curves: Vec<CurveOut<'a>>,
    }
    let curves = curves
        .iter()
        .flat_map(|(plot, cs)| {
            cs.iter().map(move |(label, points)| CurveOut {
                plot,
                label,
                points,
            })
        })
        .collect();
    let file = File {
        machine,
        rows,
        curves,
    };
    write_atomically(
        path,
        &serde_json::to_string_pretty(&file).expect("serialisable"),
    )
}
