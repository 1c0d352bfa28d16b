//! SVG plots of `lcpbatch bench` and `lcpbatch stress` (plotters), shared.

use std::path::Path;

use lcpbatch::Error;
use plotters::prelude::*;

/// Colours of successive series.
const COLORS: [RGBColor; 8] = [
    RED,
    BLUE,
    GREEN,
    MAGENTA,
    CYAN,
    BLACK,
    RGBColor(255, 140, 0),
    RGBColor(128, 0, 128),
];

fn plot_error(path: &Path) -> impl Fn(String) -> Error + '_ {
    move |e| Error::Io {
        path: path.to_path_buf(),
        source: std::io::Error::other(e),
    }
}

/// Log-scale bounds with a margin of a factor 2 on each side.
fn bounds(v: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = v
        .filter(|x| x.is_finite() && *x > 0.0)
        .fold((f64::INFINITY, 0.0f64), |(a, b), x| (a.min(x), b.max(x)));
    if !lo.is_finite() || hi <= 0.0 {
        return (1e-3, 1.0);
    }
    (lo / 2.0, (hi * 2.0).max(lo))
}

/// A labelled scatter on log–log axes: one point per (x, y, label), with
/// the label written beside it when `labels`, else in a legend by label.
pub fn scatter(
    points: &[(f64, f64, String)],
    path: &Path,
    title: &str,
    (x_desc, y_desc): (&str, &str),
    labels: bool,
) -> Result<(), Error> {
    let err = plot_error(path);
    let (xmin, xmax) = bounds(points.iter().map(|p| p.0));
    let (ymin, ymax) = bounds(points.iter().map(|p| p.1));
    let root = SVGBackend::new(path, (1100, 750)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(e.to_string()))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 20))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d((xmin..xmax).log_scale(), (ymin..ymax).log_scale())
        .map_err(|e| err(e.to_string()))?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()
        .map_err(|e| err(e.to_string()))?;
    let mut series: Vec<&str> = Vec::new();
    for p in points {
        if !series.contains(&p.2.as_str()) {
            series.push(&p.2);
        }
    }
    for (i, name) in series.iter().enumerate() {
        let c = COLORS[i % COLORS.len()];
        let pts = points.iter().filter(|p| p.2 == *name);
        let drawn = chart
            .draw_series(pts.clone().map(|p| Circle::new((p.0, p.1), 3, c.filled())))
            .map_err(|e| err(e.to_string()))?;
        if labels {
            for p in pts {
                chart
                    .draw_series(std::iter::once(Text::new(
                        p.2.clone(),
                        (p.0, p.1),
                        ("sans-serif", 10).into_font().color(&c),
                    )))
                    .map_err(|e| err(e.to_string()))?;
            }
        } else {
            drawn
                .label(name.to_string())
                .legend(move |(x, y)| Circle::new((x + 8, y), 4, c.filled()));
        }
    }
    if !labels {
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(|e| err(e.to_string()))?;
    }
    root.present().map_err(|e| err(e.to_string()))
}

/// One curve of a line plot: a label and (x, seconds-per-island) points.
pub type Curve = (String, Vec<(f64, f64)>);

/// Microseconds per island against `x_desc` (n or batch size): log y, and
/// log x when `log_x`.
pub fn curves(
    curves: &[Curve],
    path: &Path,
    title: &str,
    x_desc: &str,
    log_x: bool,
) -> Result<(), Error> {
    let err = plot_error(path);
    let xs = curves.iter().flat_map(|c| c.1.iter().map(|p| p.0));
    let (xlo, xhi) = xs
        .clone()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(x), b.max(x))
        });
    let (xmin, xmax) = bounds(xs);
    let (ymin, ymax) = bounds(curves.iter().flat_map(|c| c.1.iter().map(|p| p.1 * 1e6)));
    let root = SVGBackend::new(path, (900, 600)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| err(e.to_string()))?;
    // The two x axes have different types; the drawing is the same.
    macro_rules! draw {
        ($xr:expr) => {{
            let mut chart = ChartBuilder::on(&root)
                .caption(title, ("sans-serif", 20))
                .margin(15)
                .x_label_area_size(45)
                .y_label_area_size(70)
                .build_cartesian_2d($xr, (ymin..ymax).log_scale())
                .map_err(|e| err(e.to_string()))?;
            chart
                .configure_mesh()
                .x_desc(x_desc)
                .y_desc("microseconds per island")
                .y_label_formatter(&|v| format!("{v:.0e}"))
                .draw()
                .map_err(|e| err(e.to_string()))?;
            for (i, (label, pts)) in curves.iter().enumerate() {
                let c = COLORS[i % COLORS.len()];
                chart
                    .draw_series(LineSeries::new(
                        pts.iter().map(|&(x, y)| (x, y * 1e6)),
                        c.stroke_width(2),
                    ))
                    .map_err(|e| err(e.to_string()))?
                    .label(label.clone())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c));
            }
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .draw()
                .map_err(|e| err(e.to_string()))?;
        }};
    }
    if log_x {
        draw!((xmin..xmax).log_scale());
    } else {
        draw!((xlo - 0.5)..(xhi + 0.5));
    }
    root.present().map_err(|e| err(e.to_string()))
}
