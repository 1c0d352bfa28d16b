//! Pictures of the worlds themselves (`simulate` and `demo`): side views of
//! a few worlds at a few times (`worlds.svg`) and the same worlds in motion
//! (`worlds-animated.svg`, SMIL `<animate>`: plays in a web browser, loops
//! in real time; a viewer without SMIL shows the first frame).
//!
//! The side view looks across gravity: "up" is −g (+y in the standard
//! worlds), "right" is x made square to it, and bodies nearer the viewer
//! (+z there) are drawn over farther ones. Spheres are circles with a spoke
//! that turns with the body; boxes are the outlines of their 8 projected
//! corners; planes are the grey half-space below their line.

use std::fmt::Write as _;
use std::path::Path;

use glam::{DMat3, DQuat, DVec2, DVec3};
use lcpbatch::io::write_atomically;
use lcpbatch::world::{Shape, World};
use lcpbatch::Error;

/// Fills of successive bodies.
const FILLS: [&str; 8] = [
    "#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#b07aa1", "#76b7b2", "#edc948", "#9c755f",
];
/// Most body poses a film keeps (frames × bodies shown), which bounds the
/// animation's size (about 80 bytes a pose).
const MOST_POSES: usize = 30_000;
/// Most bodies of a world whose first poses are drawn dashed in its later
/// pictures.
const GHOSTS: usize = 9;
/// Size of one picture of one world, pixels.
const CELL: (f64, f64) = (340.0, 240.0);

/// The poses of a few worlds' bodies over a run.
pub struct Film {
    /// (index of the world in the batch, its label).
    shown: Vec<(usize, String)>,
    /// The shown worlds' bodies: shape, fixed or not (planes are fixed).
    shapes: Vec<Vec<(Shape, bool)>>,
    /// Screen axes: right, up, towards the viewer (from the first shown
    /// world's gravity).
    axes: [DVec3; 3],
    /// Every `stride` steps, and the last.
    stride: usize,
    /// (simulated time, per shown world per body: centre and rotation).
    frames: Vec<(f64, Vec<Vec<(DVec3, DQuat)>>)>,
}

impl Film {
    /// A film of `shown` worlds of the batch over `steps` steps of `dt`,
    /// its first frame the worlds as they are now.
    pub fn new(worlds: &[World], shown: Vec<(usize, String)>, steps: usize, dt: f64) -> Self {
        let g = worlds[shown[0].0].gravity();
        let up = if g.length() > 0.0 {
            -g.normalize()
        } else {
            DVec3::Y
        };
        let right = [DVec3::X, DVec3::Z]
            .into_iter()
            .map(|a| a - a.dot(up) * up)
            .find(|a| a.length() > 1e-6)
            .expect("x or z is not along gravity")
            .normalize();
        let bodies: usize = shown.iter().map(|s| worlds[s.0].bodies.len()).sum();
        // At most 30 frames a simulated second and MOST_POSES poses.
        let frames = (MOST_POSES / bodies.max(1)).clamp(2, 300);
        let stride = steps
            .div_ceil(frames)
            .max((1.0 / (30.0 * dt)).floor() as usize)
            .max(1);
        let mut film = Film {
            shapes: shown
                .iter()
                .map(|s| {
                    let bodies = &worlds[s.0].bodies;
                    bodies.iter().map(|b| (b.shape, b.fixed)).collect()
                })
                .collect(),
            shown,
            axes: [right, up, right.cross(up)],
            stride,
            frames: Vec::new(),
        };
        film.frames.push((0.0, film.poses(worlds)));
        film
    }

    fn poses(&self, worlds: &[World]) -> Vec<Vec<(DVec3, DQuat)>> {
        self.shown
            .iter()
            .map(|s| {
                let bodies = &worlds[s.0].bodies;
                bodies
                    .iter()
                    .map(|b| (b.position(), b.rotation()))
                    .collect()
            })
            .collect()
    }

    /// Whether the film takes a frame after step number `done` (from 1)
    /// of `steps`.
    pub fn wants(&self, done: usize, steps: usize) -> bool {
        done % self.stride == 0 || done == steps
    }

    /// After step number `done` (from 1) of `steps`, at `time`.
    pub fn record(&mut self, worlds: &[World], done: usize, steps: usize, time: f64) {
        if self.wants(done, steps) {
            let poses = self.poses(worlds);
            self.frames.push((time, poses));
        }
    }

    /// Screen coordinates (m, right and up) of a world point.
    fn flat(&self, p: DVec3) -> DVec2 {
        DVec2::new(p.dot(self.axes[0]), p.dot(self.axes[1]))
    }

    /// The outline of body `b` of shown world `w` in frame `f` (screen
    /// metres): a polygon, or a circle (centre, radius, spoke end); None
    /// for planes.
    fn outline(&self, w: usize, b: usize, f: usize) -> Option<Outline> {
        let (c, q) = self.frames[f].1[w][b];
        match self.shapes[w][b].0 {
            Shape::Sphere { radius } => Some(Outline::Circle(
                self.flat(c),
                radius,
                self.flat(c + q * DVec3::X * radius),
            )),
            Shape::Box { half_extents } => {
                let r = DMat3::from_quat(q);
                let h = DVec3::from_array(half_extents);
                let corners: Vec<DVec2> = (0..8)
                    .map(|k| {
                        let s = DVec3::new(
                            if k & 1 == 0 { -1.0 } else { 1.0 },
                            if k & 2 == 0 { -1.0 } else { 1.0 },
                            if k & 4 == 0 { -1.0 } else { 1.0 },
                        );
                        self.flat(c + r * (s * h))
                    })
                    .collect();
                Some(Outline::Polygon(convex_hull(corners)))
            }
            Shape::Plane { .. } => None,
        }
    }

    /// Screen bounds (m) of shown world `w`, with a margin: every frame's
    /// heights; across, the first frame and 90% of the bodies' positions
    /// over the run (a ball rolling far away leaves the picture rather than
    /// shrink it).
    fn bounds(&self, w: usize) -> (DVec2, DVec2) {
        let (mut lo, mut hi) = (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
        let mut across = Vec::new();
        for f in 0..self.frames.len() {
            for b in 0..self.shapes[w].len() {
                let pts = match self.outline(w, b, f) {
                    Some(Outline::Polygon(p)) => p,
                    Some(Outline::Circle(c, r, _)) => {
                        vec![c - DVec2::splat(r), c + DVec2::splat(r)]
                    }
                    None => continue,
                };
                for p in pts.into_iter().filter(|p| p.is_finite()) {
                    if f == 0 {
                        lo.x = lo.x.min(p.x);
                        hi.x = hi.x.max(p.x);
                    }
                    lo.y = lo.y.min(p.y);
                    hi.y = hi.y.max(p.y);
                    across.push(p.x);
                }
            }
        }
        if !across.is_empty() {
            across.sort_by(f64::total_cmp);
            let at = |q: f64| across[((across.len() - 1) as f64 * q).round() as usize];
            lo.x = lo.x.min(at(0.05));
            hi.x = hi.x.max(at(0.95));
        }
        if !(lo.is_finite() && hi.is_finite()) {
            (lo, hi) = (DVec2::splat(-1.0), DVec2::splat(1.0));
        }
        let pad = 0.08 * (hi - lo).max_element().max(1.0);
        (lo - DVec2::splat(pad), hi + DVec2::splat(pad))
    }

    /// One scale for every picture (the largest at which each world fits),
    /// so that a metre is as long in each.
    fn scale(&self) -> f64 {
        (0..self.shown.len())
            .map(|w| View::fit(self.bounds(w)))
            .fold(f64::INFINITY, f64::min)
    }

    /// The frames nearest to 0, a tenth, a third and all of the run.
    fn snapshot_frames(&self) -> Vec<usize> {
        let end = self.frames.last().expect("frame 0").0;
        let mut picked: Vec<usize> = Vec::new();
        for t in [0.0, end / 10.0, end / 3.0, end] {
            let f = (0..self.frames.len())
                .min_by(|&a, &b| {
                    let d = |k: usize| (self.frames[k].0 - t).abs();
                    d(a).total_cmp(&d(b))
                })
                .expect("frame 0");
            if !picked.contains(&f) {
                picked.push(f);
            }
        }
        picked
    }

    /// Writes `worlds.svg` and `worlds-animated.svg` to `out`, titled by
    /// `title` (lines).
    pub fn write(&self, out: &Path, title: &[String]) -> Result<(), Error> {
        let snaps = self.snapshot_frames();
        let rows = self.shown.len();
        let (left, top) = (170.0, 30.0 + 20.0 * title.len() as f64 + 25.0);
        let scale = self.scale();
        let views: Vec<View> = (0..rows)
            .map(|w| View::new(self.bounds(w), scale, left, 0.0))
            .collect();
        let width = left + CELL.0 * snaps.len() as f64 + 10.0;
        let height = top + views.iter().map(|v| v.h).sum::<f64>() + 30.0;
        let mut svg = header(width, height, title);
        for (k, &f) in snaps.iter().enumerate() {
            let x = left + CELL.0 * (k as f64 + 0.5);
            let t = self.frames[f].0;
            let _ = writeln!(
                svg,
                r#"<text x="{x:.1}" y="{:.1}" text-anchor="middle" font-size="14">t = {t:.2} s</text>"#,
                top - 8.0
            );
        }
        let mut y = top;
        for (w, view) in views.into_iter().enumerate() {
            let view = View { y, ..view };
            y += view.h;
            let _ = writeln!(
                svg,
                r#"<text x="10" y="{:.1}" font-size="14">{}</text>"#,
                view.y + view.h / 2.0,
                escape(&self.shown[w].1)
            );
            for (k, &f) in snaps.iter().enumerate() {
                let v = view.shifted(CELL.0 * k as f64);
                let clip = format!("c{w}_{k}");
                v.open(&mut svg, &clip, &self.planes(w, 0, &v));
                // The first frame's outlines, dashed, behind the later ones
                // (where they do not crowd the picture).
                if f != 0 && self.shapes[w].len() <= GHOSTS {
                    for b in self.depth_order(w, 0) {
                        if let Some(o) = self.outline(w, b, 0) {
                            let _ = writeln!(
                                svg,
                                r##"<path d="{}" fill="none" stroke="#999" stroke-dasharray="4 3"/>"##,
                                o.path(&v)
                            );
                        }
                    }
                }
                for b in self.depth_order(w, f) {
                    if let Some(o) = self.outline(w, b, f) {
                        let _ = writeln!(svg, r#"<path d="{}" {}/>"#, o.path(&v), self.style(w, b));
                    }
                }
                v.close(&mut svg, k == 0);
            }
        }
        let _ = writeln!(
            svg,
            r##"<text x="10" y="{:.1}" font-size="12" fill="#555">Side view across gravity, one scale for all; dashed (worlds of a few bodies): where the bodies were at t = 0.</text>"##,
            height - 10.0
        );
        svg.push_str("</svg>\n");
        write_atomically(&out.join("worlds.svg"), &svg)?;
        write_atomically(&out.join("worlds-animated.svg"), &self.animation(title))
    }

    /// The shown worlds side by side, each body's outline changing frame by
    /// frame, in real time, looping.
    fn animation(&self, title: &[String]) -> String {
        let top = 30.0 + 20.0 * title.len() as f64 + 10.0;
        let cols = self.shown.len();
        let width = (CELL.0 * cols as f64 + 20.0).max(620.0);
        let scale = self.scale();
        let views: Vec<View> = (0..cols)
            .map(|w| View::new(self.bounds(w), scale, 10.0 + CELL.0 * w as f64, top + 20.0))
            .collect();
        let cell_h = views.iter().map(|v| v.h).fold(0.0, f64::max);
        let height = top + 20.0 + cell_h + 60.0;
        let end = self.frames.last().expect("frame 0").0;
        let dur = end.max(0.1);
        let mut svg = header(width, height, title);
        for w in 0..cols {
            let x = 10.0 + CELL.0 * w as f64;
            let _ = writeln!(
                svg,
                r#"<text x="{:.1}" y="{:.1}" text-anchor="middle" font-size="14">{}</text>"#,
                x + CELL.0 / 2.0,
                top + 12.0,
                escape(&self.shown[w].1)
            );
            // Bottoms aligned.
            let v = View {
                y: views[w].y + cell_h - views[w].h,
                ..views[w]
            };
            v.open(&mut svg, &format!("a{w}"), &self.planes(w, 0, &v));
            for b in self.depth_order(w, 0) {
                let paths: Vec<String> = (0..self.frames.len())
                    .filter_map(|f| self.outline(w, b, f).map(|o| o.path(&v)))
                    .collect();
                if paths.is_empty() {
                    continue;
                }
                let _ = writeln!(
                    svg,
                    r#"<path d="{}" {}><animate attributeName="d" dur="{dur:.3}s" repeatCount="indefinite" calcMode="discrete" values="{}"/></path>"#,
                    paths[0],
                    self.style(w, b),
                    paths.join(";")
                );
            }
            v.close(&mut svg, w == 0);
        }
        // A clock: a bar that fills over the run.
        let y = top + 20.0 + cell_h + 15.0;
        let bar = width - 160.0;
        let _ = writeln!(
            svg,
            r##"<rect x="80" y="{y:.1}" width="{bar:.1}" height="8" fill="#eee" stroke="#999"/>
<rect x="80" y="{y:.1}" width="0" height="8" fill="#4e79a7"><animate attributeName="width" from="0" to="{bar:.1}" dur="{dur:.3}s" repeatCount="indefinite"/></rect>
<text x="70" y="{:.1}" text-anchor="end" font-size="12">t = 0</text>
<text x="{:.1}" y="{:.1}" font-size="12">{end:.2} s</text>
<text x="10" y="{:.1}" font-size="12" fill="#555">Side view across gravity, played in real time ({} frames), looping; a viewer without SVG animation shows t = 0.</text>"##,
            y + 8.0,
            80.0 + bar + 8.0,
            y + 8.0,
            y + 35.0,
            self.frames.len()
        );
        svg.push_str("</svg>\n");
        svg
    }

    /// Bodies of shown world `w` far to near in frame `f`.
    fn depth_order(&self, w: usize, f: usize) -> Vec<usize> {
        let depth = |b: usize| self.frames[f].1[w][b].0.dot(self.axes[2]);
        let mut order: Vec<usize> = (0..self.shapes[w].len()).collect();
        order.sort_by(|&a, &b| depth(a).total_cmp(&depth(b)));
        order
    }

    fn style(&self, w: usize, b: usize) -> String {
        let fill = if self.shapes[w][b].1 {
            "#888"
        } else {
            FILLS[b % FILLS.len()]
        };
        format!(r##"fill="{fill}" fill-opacity="0.85" stroke="#222" stroke-width="1""##)
    }

    /// The planes of shown world `w` (frame `f`) as screen polygons: each
    /// the part of the view on the solid side of its line.
    fn planes(&self, w: usize, f: usize, v: &View) -> Vec<String> {
        let mut out = Vec::new();
        for (b, (shape, _)) in self.shapes[w].iter().enumerate() {
            let Shape::Plane { normal } = *shape else {
                continue;
            };
            let n = self.flat(DVec3::from_array(normal));
            if n.length() < 1e-9 {
                continue; // seen edge-on: it faces the viewer
            }
            let p = self.flat(self.frames[f].1[w][b].0);
            let (lo, hi) = v.bounds;
            let rect = [lo, DVec2::new(hi.x, lo.y), hi, DVec2::new(lo.x, hi.y)];
            let inside = clip_half_plane(&rect, n, p);
            if inside.len() >= 3 {
                out.push(Outline::Polygon(inside).path(v));
            }
        }
        out
    }
}

/// A body's outline on screen (metres).
enum Outline {
    Polygon(Vec<DVec2>),
    /// Centre, radius, end of the spoke.
    Circle(DVec2, f64, DVec2),
}

impl Outline {
    /// SVG path data in `v`'s pixels.
    fn path(&self, v: &View) -> String {
        let mut d = String::new();
        match self {
            Outline::Polygon(pts) => {
                for (k, p) in pts.iter().enumerate() {
                    let s = v.px(*p);
                    let _ = write!(
                        d,
                        "{}{:.1} {:.1} ",
                        if k == 0 { "M" } else { "L" },
                        s.x,
                        s.y
                    );
                }
                d.push('Z');
            }
            Outline::Circle(c, r, spoke) => {
                let (s, e) = (v.px(*c), v.px(*spoke));
                let r = r * v.scale;
                let _ = write!(
                    d,
                    "M{:.1} {:.1} a{r:.1} {r:.1} 0 1 0 {:.1} 0 a{r:.1} {r:.1} 0 1 0 {:.1} 0 Z M{:.1} {:.1} L{:.1} {:.1}",
                    s.x - r,
                    s.y,
                    2.0 * r,
                    -2.0 * r,
                    s.x,
                    s.y,
                    e.x,
                    e.y
                );
            }
        }
        d
    }
}

/// A picture of one world: screen metres `bounds` drawn into a cell whose
/// top left is (`x`, `y`) pixels, metres square.
#[derive(Clone, Copy)]
struct View {
    bounds: (DVec2, DVec2),
    /// Height of the cell, pixels.
    h: f64,
    x: f64,
    y: f64,
    scale: f64,
    /// Pixel offset that centres the picture in its cell.
    centre: DVec2,
}

impl View {
    /// The largest scale (pixels a metre) at which `bounds` fit a cell.
    fn fit(bounds: (DVec2, DVec2)) -> f64 {
        let size = bounds.1 - bounds.0;
        ((CELL.0 - 10.0) / size.x).min((CELL.1 - 10.0) / size.y)
    }

    /// `bounds` at `scale` in a cell as wide as any and as high as they
    /// need (within limits), grown about their centre to fill it.
    fn new(bounds: (DVec2, DVec2), scale: f64, x: f64, y: f64) -> Self {
        let h = ((bounds.1.y - bounds.0.y) * scale + 10.0).clamp(100.0, CELL.1);
        let half = DVec2::new(CELL.0 - 10.0, h - 10.0) / scale / 2.0;
        // Centred across; the lowest point (by the ground) at the bottom.
        let mid = DVec2::new((bounds.0.x + bounds.1.x) / 2.0, bounds.0.y + half.y);
        View {
            bounds: (mid - half, mid + half),
            h,
            x,
            y,
            scale,
            centre: DVec2::new(5.0, 5.0),
        }
    }

    fn shifted(&self, dx: f64) -> View {
        View {
            x: self.x + dx,
            ..*self
        }
    }

    /// Pixels of a screen point (y down).
    fn px(&self, p: DVec2) -> DVec2 {
        DVec2::new(
            self.x + self.centre.x + (p.x - self.bounds.0.x) * self.scale,
            self.y + self.centre.y + (self.bounds.1.y - p.y) * self.scale,
        )
    }

    /// The cell's frame, clip and planes.
    fn open(&self, svg: &mut String, id: &str, planes: &[String]) {
        let (w, h) = (CELL.0 - 10.0, self.h - 10.0);
        let (x, y) = (self.x + 5.0, self.y + 5.0);
        let _ = writeln!(
            svg,
            r##"<clipPath id="{id}"><rect x="{x:.1}" y="{y:.1}" width="{w:.1}" height="{h:.1}"/></clipPath>
<rect x="{x:.1}" y="{y:.1}" width="{w:.1}" height="{h:.1}" fill="#f7fbff" stroke="#bbb"/>
<g clip-path="url(#{id})">"##
        );
        for p in planes {
            let _ = writeln!(svg, r##"<path d="{p}" fill="#d9d9d9" stroke="#777"/>"##);
        }
    }

    /// Closes the clip group; with `scale_bar`, a 1 m bar in the corner.
    fn close(&self, svg: &mut String, scale_bar: bool) {
        svg.push_str("</g>\n");
        if scale_bar {
            let (x, y) = (self.x + 12.0, self.y + 20.0);
            let len = self.scale;
            let _ = writeln!(
                svg,
                r##"<path d="M{x:.1} {y:.1} h{len:.1}" stroke="#000" stroke-width="2"/><text x="{:.1}" y="{:.1}" font-size="11">1 m</text>"##,
                x + len + 4.0,
                y + 4.0
            );
        }
    }
}

/// The start of an SVG of `width` × `height` with `title`'s lines on top.
fn header(width: f64, height: f64, title: &[String]) -> String {
    let mut svg = format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width:.0}" height="{height:.0}" viewBox="0 0 {width:.0} {height:.0}" font-family="sans-serif">
<rect width="100%" height="100%" fill="white"/>
"#
    );
    for (k, line) in title.iter().enumerate() {
        let _ = writeln!(
            svg,
            r#"<text x="10" y="{}" font-size="{}">{}</text>"#,
            24 + 20 * k,
            if k == 0 { 16 } else { 13 },
            escape(line)
        );
    }
    svg
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// Convex hull of points (Andrew's monotone chain), counter-clockwise.
fn convex_hull(mut p: Vec<DVec2>) -> Vec<DVec2> {
    p.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    let cross = |o: DVec2, a: DVec2, b: DVec2| (a - o).perp_dot(b - o);
    let mut hull: Vec<DVec2> = Vec::with_capacity(p.len() + 1);
    for pass in 0..2 {
        let start = hull.len();
        let pts: Box<dyn Iterator<Item = &DVec2>> = if pass == 0 {
            Box::new(p.iter())
        } else {
            Box::new(p.iter().rev())
        };
        for &q in pts {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], q) <= 0.0
            {
                hull.pop();
            }
            hull.push(q);
        }
        hull.pop();
    }
    hull
}

/// The part of polygon `poly` on the solid side of the line through `p`
/// with outward normal `n` (n·(x − p) ≤ 0): one Sutherland–Hodgman pass.
fn clip_half_plane(poly: &[DVec2], n: DVec2, p: DVec2) -> Vec<DVec2> {
    let side = |x: DVec2| n.dot(x - p);
    let mut out = Vec::new();
    for k in 0..poly.len() {
        let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
        let (sa, sb) = (side(a), side(b));
        if sa <= 0.0 {
            out.push(a);
        }
        if (sa <= 0.0) != (sb <= 0.0) {
            out.push(a + (b - a) * (sa / (sa - sb)));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_square_seen_flat_is_its_four_corners_and_the_ground_is_below_zero() {
        let pts = vec![
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(0.5, 0.5),
            DVec2::new(1.0, 1.0),
            DVec2::new(0.0, 1.0),
        ];
        assert_eq!(convex_hull(pts).len(), 4);
        let rect = [
            DVec2::new(-1.0, -1.0),
            DVec2::new(1.0, -1.0),
            DVec2::new(1.0, 1.0),
            DVec2::new(-1.0, 1.0),
        ];
        let ground = clip_half_plane(&rect, DVec2::Y, DVec2::ZERO);
        assert_eq!(ground.len(), 4);
        assert!(ground.iter().all(|q| q.y <= 0.0));
    }
}
