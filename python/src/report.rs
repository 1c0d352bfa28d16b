//! A report as a Python dict, and the codes of paths and statuses.
//!
//! A long batch is solved in chunks (so that Ctrl-C is seen between them);
//! the caller sees one report, the chunks' joined by [`Report::append`].

use lcpbatch::report::{DeviceKind, GpuFigures, SolvePath};
use lcpbatch::{Report, Status};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// Every solve path, in the order of the codes handed to Python.
pub(crate) const PATHS: [SolvePath; 11] = SolvePath::ALL;

/// The code of `path` (its index in [`PATHS`]).
pub(crate) fn path_code(path: SolvePath) -> i8 {
    PATHS
        .iter()
        .position(|&p| p == path)
        .unwrap_or(PATHS.len() - 1) as i8
}

/// The code of `status` (its index in [`Status::ALL`]).
pub(crate) fn status_code(status: Status) -> i8 {
    Status::ALL
        .iter()
        .position(|&s| s == status)
        .unwrap_or(Status::ALL.len() - 1) as i8
}

/// "cpu", "hardware_gpu" or "software_gpu".
pub(crate) fn device_kind_name(kind: DeviceKind) -> &'static str {
    match kind {
        DeviceKind::Cpu => "cpu",
        DeviceKind::HardwareGpu => "hardware_gpu",
        DeviceKind::SoftwareGpu => "software_gpu",
    }
}

/// A dict of (name, value) pairs.
fn dict_of<'py, V: IntoPyObject<'py> + Copy>(
    py: Python<'py>,
    items: &[(&str, V)],
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for (name, v) in items {
        d.set_item(*name, *v)?;
    }
    Ok(d)
}

/// The report's batch figures as a dict (per-island data goes in arrays).
pub(crate) fn to_dict<'py>(
    py: Python<'py>,
    r: &Report,
    chunks: usize,
) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("text", r.to_string())?;
    d.set_item("device", &r.device.name)?;
    d.set_item("device_kind", device_kind_name(r.device.kind))?;
    d.set_item("precision", r.device.precision.name())?;
    d.set_item("choice", &r.choice)?;
    d.set_item("fallback", r.fallback.as_deref())?;
    d.set_item("counts", dict_of(py, &r.counts.named())?)?;
    let statuses: Vec<(&str, usize)> = Status::ALL
        .iter()
        .zip(r.statuses)
        .map(|(s, n)| (s.name(), n))
        .collect();
    d.set_item("statuses", dict_of(py, &statuses)?)?;
    d.set_item("max_error", r.max_error.map(|(e, _)| e))?;
    d.set_item("max_error_index", r.max_error.map(|(_, i)| i))?;
    d.set_item("timings", dict_of(py, &r.timings.named())?)?;
    d.set_item("gpu", r.gpu.map(|g| gpu_dict(py, &g)).transpose()?)?;
    d.set_item("friction_islands", r.friction.len())?;
    let statuses: Vec<(&str, usize)> = Status::ALL
        .iter()
        .zip(r.friction_statuses)
        .map(|(s, n)| (s.name(), n))
        .collect();
    d.set_item("friction_statuses", dict_of(py, &statuses)?)?;
    d.set_item("max_coulomb_error", r.max_coulomb_error.map(|(e, _)| e))?;
    d.set_item(
        "max_coulomb_error_index",
        r.max_coulomb_error.map(|(_, i)| i),
    )?;
    d.set_item("chunks", chunks)?;
    Ok(d)
}

fn gpu_dict<'py>(py: Python<'py>, g: &GpuFigures) -> PyResult<Bound<'py, PyDict>> {
    let d = dict_of(
        py,
        &[
            ("chunks", g.chunks),
            ("dispatches", g.dispatches),
            ("rounds", g.rounds),
            ("tree_decided", g.tree_decided),
            ("tree_undecided", g.tree_undecided),
        ],
    )?;
    let floats = [
        ("max_gpu_error", g.max_gpu_error),
        ("max_velocity_deviation", g.max_velocity_deviation),
        ("pack_seconds", g.pack_seconds),
        ("upload_seconds", g.upload_seconds),
        ("kernel_seconds", g.kernel_seconds),
        ("readback_seconds", g.readback_seconds),
        ("check_seconds", g.check_seconds),
        ("repair_seconds", g.repair_seconds),
        ("report_seconds", g.report_seconds),
        ("overlapped_seconds", g.overlapped_seconds),
    ];
    for (name, v) in floats {
        d.set_item(name, v)?;
    }
    d.set_item("kernel_device_seconds", g.kernel_device_seconds)?;
    Ok(d)
}
