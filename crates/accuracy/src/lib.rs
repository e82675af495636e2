//! The accuracy harness: a fixed-point render against the float reference.
//!
//! This is the one place outside tests where `model` and `reference` meet. It
//! renders a triangle list both ways and reports, as a table and as JSON:
//! pixels whose coverage differs (and how many of them are documented ties),
//! colour max and mean absolute error and PSNR, depth max error in LSBs of the
//! fixed-point depth, the worst pixels, and the cycle model's prediction.
//!
//! The reference interpolates colour the way the method does (screen-linear for
//! scanline, perspective-correct for vector when the input carries w), so the
//! numbers measure the number formats; [`Report::vs_perspective`] adds the
//! error against the perspective-correct image where that differs.
//!
//! **Documented ties.** A pixel may legitimately differ when
//! * its centre lies within one `xy` LSB of an edge: snapping moved the edge;
//! * the float and snapped depths at it fall on different sides of 0 or 1: z
//!   clipping follows the snapped vertices; or its depth is above the largest
//!   depth-buffer value (the far-plane tie);
//! * the two renders' winning triangles there have snapped-vertex depths
//!   within two depth LSBs, or in the opposite order to their float depths:
//!   which is nearer is a tie.
//!
//! Colour and depth errors are measured where the same triangle won the pixel
//! in both renders (each frame records its writers for this purpose).

pub mod texture;

use fx::Formats;
use model::cycles::{scanline_frame, vector_frame, FrameCycles, Timing};
use model::pixel_out::Framebuffer;
use model::render::{render as model_render, Method, Options as ModelOptions};
use reference::{Cull, Frame, Options as RefOptions};
use scene::measure::{edge_distance, inside, plane_z};
use scene::{Triangle, Trilist};
use serde::Serialize;

/// What to compare.
#[derive(Clone, Copy, Debug)]
pub struct Setup {
    pub method: Method,
    pub formats: Formats,
    pub cull_back: bool,
    pub background: [f64; 3],
    pub timing: Timing,
}

/// Colour errors of one comparison.
#[derive(Clone, Debug, Default, Serialize, PartialEq)]
pub struct Errors {
    /// Largest |fixed - reference| over the channels of pixels the same triangle
    /// wrote in both (8-bit LSBs, against the unrounded reference).
    pub color_max: f64,
    /// Mean of that over the same channels.
    pub color_mean: f64,
    /// Of those pixels, how many are more than 1 LSB off.
    pub color_over_1: u64,
    /// PSNR of the whole 8-bit image against the rounded reference (dB;
    /// infinite when identical).
    pub psnr_db: f64,
}

/// One of the worst pixels.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Worst {
    pub x: u32,
    pub y: u32,
    pub color_error: f64,
    pub fixed: [u8; 3],
    pub reference: [u8; 3],
    /// Whether the same triangle won the pixel in both renders.
    pub same_triangle: bool,
}

/// The comparison of one render.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Report {
    pub method: String,
    pub width: u32,
    pub height: u32,
    pub formats: Formats,
    /// Pixels written by the fixed-point render / by the reference.
    pub pixels_fixed: u64,
    pub pixels_reference: u64,
    /// Depth-test passes of the fixed-point render: a pixel written twice counts twice.
    pub pixels_written: u64,
    /// Pixels written by exactly one of the two.
    pub coverage_differs: u64,
    /// Of those, how many no documented tie explains.
    pub coverage_unexplained: u64,
    /// Pixels both wrote, but from different triangles.
    pub winner_differs: u64,
    /// Of those, how many no documented tie explains.
    pub winner_unexplained: u64,
    pub errors: Errors,
    /// The same against the perspective-correct reference, when the method
    /// interpolates screen-linearly and the input carries w.
    pub vs_perspective: Option<Errors>,
    /// Largest and mean depth difference where the same triangle won (LSBs of
    /// the fixed depth; most of it is vertex snapping).
    pub depth_max_lsb: f64,
    pub depth_mean_lsb: f64,
    pub worst: Vec<Worst>,
    /// Triangles the fixed-point render could not draw (input or overflow).
    pub problems: u64,
    /// Triangles it dropped as of zero area once their vertices snapped to the `xy` format
    /// (a sliver thinner than the subpixel grid).
    pub degenerate: u64,
    pub cycles: u64,
    pub pixels_per_clock: f64,
}

/// A fixed-point frame to compare with the reference: what a pipeline drew.
struct Fixed {
    method: String,
    fb: Framebuffer,
    /// Triangles (or spans) it could not draw: input out of range, overflow.
    problems: u64,
    /// Triangles of zero area once snapped.
    degenerate: u64,
    pixels_written: u64,
    cycles: u64,
}

/// Renders `list` both ways and compares.
pub fn compare(list: &Trilist, s: &Setup) -> Report {
    let mopts = ModelOptions {
        method: s.method,
        cull: model_cull(s.cull_back),
        analysis: true,
        background: background8(s.background),
    };
    let fixed = model_render(list, &s.formats, &mopts, &mut |_| {});
    let FrameCycles { total: cycles, .. } = match s.method {
        Method::Scanline => scanline_frame(&fixed.work, &s.timing),
        Method::Vector { .. } => vector_frame(&fixed.work, &s.timing),
    };
    let perspective = matches!(s.method, Method::Vector { perspective: true, .. });
    let frame = Fixed {
        method: method_name(s.method),
        problems: fixed.problems.len() as u64,
        degenerate: fixed.stats.degenerate,
        pixels_written: fixed.stats.pixels_written,
        fb: fixed.fb,
        cycles,
    };
    against_reference(list, s, perspective, frame)
}

/// Draws `list` with 000's shading engines behind the scanline pipeline's spans
/// (`model::se::array`, `render --engine se`) and compares with the reference, screen-linear
/// as the scanline method; `s.method` is not used. The cycles are the whole SE back end's
/// (`raster_top` with `METHOD = 2`: the scanline front end at `s.timing`, `se_cmd` and the
/// engines; `model::cycles::se_frame`). Problems: triangles whose vertices do not fit the
/// input formats, and spans whose line overflowed an engine's words. Errs when no SE array
/// fits the screen or the formats.
pub fn compare_se(list: &Trilist, s: &Setup) -> Result<Report, String> {
    let (cull, background) = (model_cull(s.cull_back), background8(s.background));
    let r = model::se::array::render(list, &s.formats, cull, background)?;
    let cycles = model::se::array::back_end_cycles(list, &s.formats, cull, background, &s.timing)?;
    let frame = Fixed {
        method: format!("se ({} engines)", r.engines),
        problems: r.stats.input_rejected + r.ends_overflowed,
        degenerate: r.stats.degenerate,
        pixels_written: r.pixels_written,
        fb: r.fb,
        cycles,
    };
    Ok(against_reference(list, s, false, frame))
}

fn model_cull(back: bool) -> model::cull_sort::Cull {
    if back {
        model::cull_sort::Cull::Back
    } else {
        model::cull_sort::Cull::None
    }
}

/// The background as the 8-bit colour the fixed-point pipelines clear to.
fn background8(bg: [f64; 3]) -> [u8; 3] {
    bg.map(|c| c.round().clamp(0.0, 255.0) as u8)
}

/// `fixed` against the reference render of `list` (perspective-correct when
/// `perspective`, as the method interpolates).
fn against_reference(list: &Trilist, s: &Setup, perspective: bool, fixed: Fixed) -> Report {
    let cull = if s.cull_back { Cull::Back } else { Cull::None };
    let ropts = RefOptions { cull, ignore_w: !perspective, background: s.background };
    let (reference, _) = reference::render(list, &ropts, &mut |_| {});
    let cycles = fixed.cycles;
    let ties = Ties { tris: &list.triangles, f: &s.formats };
    let (errs, worst) = errors(&fixed.fb, &reference);
    let vs_perspective = (!perspective && list.triangles.iter().flatten().any(|v| v.w.is_some())).then(|| {
        let (persp, _) = reference::render(list, &RefOptions { ignore_w: false, ..ropts }, &mut |_| {});
        errors(&fixed.fb, &persp).0
    });
    let zscale = (s.formats.z.frac as f64).exp2();
    let mut r = Report {
        method: fixed.method,
        width: list.width,
        height: list.height,
        formats: s.formats,
        pixels_fixed: 0,
        pixels_reference: 0,
        pixels_written: fixed.pixels_written,
        coverage_differs: 0,
        coverage_unexplained: 0,
        winner_differs: 0,
        winner_unexplained: 0,
        errors: errs,
        vs_perspective,
        depth_max_lsb: 0.0,
        depth_mean_lsb: 0.0,
        worst,
        problems: fixed.problems,
        degenerate: fixed.degenerate,
        cycles,
        pixels_per_clock: if cycles > 0 { fixed.pixels_written as f64 / cycles as f64 } else { 0.0 },
    };
    let fixed = fixed.fb;
    let (mut depth_sum, mut same) = (0.0, 0u64);
    for i in 0..fixed.written.len() {
        let (x, y) = (i as u32 % list.width, i as u32 / list.width);
        let (a, b) = (fixed.writer[i], reference.writer[i]);
        r.pixels_fixed += fixed.written[i] as u64;
        r.pixels_reference += reference.written[i] as u64;
        match (fixed.written[i], reference.written[i]) {
            (true, true) if a == b => {
                let e = (fixed.depth[i] as f64 - reference.depth[i] * zscale).abs();
                r.depth_max_lsb = r.depth_max_lsb.max(e);
                depth_sum += e;
                same += 1;
            }
            (true, true) => {
                r.winner_differs += 1;
                r.winner_unexplained += !ties.winner(a as usize, b as usize, x, y) as u64;
            }
            (false, false) => {}
            _ => {
                r.coverage_differs += 1;
                r.coverage_unexplained += !ties.coverage(x, y) as u64;
            }
        }
    }
    r.depth_mean_lsb = if same > 0 { depth_sum / same as f64 } else { 0.0 };
    r
}

/// A method's name as the CLI spells it.
pub fn method_name(m: Method) -> String {
    match m {
        Method::Scanline => "scanline".into(),
        Method::Vector { lanes: 1, .. } => "vector (1 lane)".into(),
        Method::Vector { lanes, .. } => format!("vector ({lanes} lanes)"),
    }
}

/// Colour errors between the fixed-point framebuffer and a reference frame, and
/// the ten worst pixels.
fn errors(fixed: &Framebuffer, reference: &Frame) -> (Errors, Vec<Worst>) {
    let r8 = reference.rgb8();
    let (mut sum, mut n, mut sq) = (0.0, 0u64, 0.0);
    let mut e = Errors::default();
    let mut worst = Vec::new();
    for (i, r) in r8.iter().enumerate() {
        let f = fixed.rgb[i];
        sq += (0..3).map(|c| (f[c] as f64 - r[c] as f64).powi(2)).sum::<f64>();
        if !(fixed.written[i] && reference.written[i]) {
            continue;
        }
        let err = (0..3).map(|c| (f[c] as f64 - reference.color[i][c]).abs()).fold(0.0, f64::max);
        let same_triangle = fixed.writer[i] == reference.writer[i];
        if same_triangle {
            sum += (0..3).map(|c| (f[c] as f64 - reference.color[i][c]).abs()).sum::<f64>();
            n += 3;
            e.color_max = e.color_max.max(err);
            e.color_over_1 += (err > 1.0) as u64;
        }
        let (x, y) = (i as u32 % reference.width, i as u32 / reference.width);
        worst.push(Worst { x, y, color_error: err, fixed: f, reference: *r, same_triangle });
    }
    worst.sort_by(|a, b| b.color_error.total_cmp(&a.color_error));
    worst.truncate(10);
    let mse = sq / (3 * r8.len()) as f64;
    e.psnr_db = if mse == 0.0 { f64::INFINITY } else { 10.0 * (255.0f64 * 255.0 / mse).log10() };
    e.color_mean = if n > 0 { sum / n as f64 } else { 0.0 };
    (e, worst)
}

/// Finds the documented ties at a pixel (see the module doc).
struct Ties<'a> {
    tris: &'a [Triangle],
    f: &'a Formats,
}

impl Ties<'_> {
    /// How far snapping can move an edge past a centre, in pixels.
    fn edge_tie(&self) -> f64 {
        (-(self.f.xy.frac as f64)).exp2()
    }

    /// One depth LSB, and the largest depth the buffer holds.
    fn depth_lsb(&self) -> (f64, f64) {
        let lsb = (-(self.f.z.frac as f64)).exp2();
        (lsb, 1.0 - lsb)
    }

    /// The triangle's depth at (cx, cy) from its float vertices and from its
    /// vertices snapped to the input formats (what the hardware interpolates).
    fn depths(&self, t: &Triangle, cx: f64, cy: f64) -> Option<(f64, f64)> {
        let snap = |fm: fx::Fmt, v: f64| fm.from_f64(v).map(|r| fm.to_f64(r));
        let mut q = *t;
        for v in &mut q {
            (v.x, v.y, v.z) = (snap(self.f.xy, v.x)?, snap(self.f.xy, v.y)?, snap(self.f.z, v.z)?);
        }
        Some((plane_z(t, cx, cy)?, plane_z(&q, cx, cy)?))
    }

    /// Whether a coverage difference at (x, y) is a documented tie: an edge
    /// within snapping distance, or a triangle there whose depth straddles a z
    /// boundary (float vs snapped, within an LSB) or lies beyond the buffer's range.
    fn coverage(&self, x: u32, y: u32) -> bool {
        let (cx, cy) = (x as f64 + 0.5, y as f64 + 0.5);
        let (lsb, zmax) = self.depth_lsb();
        self.tris.iter().any(|t| {
            edge_distance(t, cx, cy) <= self.edge_tie()
                || (inside(t, cx, cy)
                    && self.depths(t, cx, cy).is_some_and(|(fl, sn)| {
                        let boundary =
                            |b: f64| (fl - b) * (sn - b) <= 0.0 || (fl - b).abs() <= lsb || (sn - b).abs() <= lsb;
                        boundary(0.0) || boundary(1.0) || fl > zmax - lsb
                    }))
        })
    }

    /// Whether triangle `a` winning (x, y) in fixed point and `b` in the
    /// reference is a documented tie: their snapped depths are within two LSBs
    /// (rounding), their order flips between float and snapped vertices, or a
    /// coverage tie let one of them in.
    fn winner(&self, a: usize, b: usize, x: u32, y: u32) -> bool {
        let (cx, cy) = (x as f64 + 0.5, y as f64 + 0.5);
        let (lsb, _) = self.depth_lsb();
        let near_edge = |t: &Triangle| edge_distance(t, cx, cy) <= self.edge_tie();
        let (ta, tb) = (&self.tris[a], &self.tris[b]);
        if near_edge(ta) || near_edge(tb) || self.coverage(x, y) {
            return true;
        }
        match (self.depths(ta, cx, cy), self.depths(tb, cx, cy)) {
            (Some((fa, sa)), Some((fb, sb))) => (sa - sb).abs() <= 2.0 * lsb || (fa < fb) != (sa < sb),
            _ => false,
        }
    }
}

impl Report {
    /// A readable table.
    pub fn table(&self) -> String {
        let mut s = String::new();
        let mut row = |k: &str, v: String| s.push_str(&format!("| {k:<34} | {v:>24} |\n"));
        row("method", self.method.clone());
        row("screen", format!("{}x{}", self.width, self.height));
        row("pixels written (fixed / float)", format!("{} / {}", self.pixels_fixed, self.pixels_reference));
        row("coverage differs (unexplained)", format!("{} ({})", self.coverage_differs, self.coverage_unexplained));
        row("other triangle won (unexplained)", format!("{} ({})", self.winner_differs, self.winner_unexplained));
        row(
            "colour max / mean abs error (LSB)",
            format!("{:.3} / {:.4}", self.errors.color_max, self.errors.color_mean),
        );
        row("pixels with colour > 1 LSB off", self.errors.color_over_1.to_string());
        row("PSNR (dB)", format!("{:.2}", self.errors.psnr_db));
        if let Some(p) = &self.vs_perspective {
            row("vs perspective-correct: max / PSNR", format!("{:.1} / {:.2} dB", p.color_max, p.psnr_db));
        }
        row("depth max / mean error (LSB)", format!("{:.2} / {:.3}", self.depth_max_lsb, self.depth_mean_lsb));
        row("triangles not drawn (problems)", self.problems.to_string());
        row("predicted cycles per frame", self.cycles.to_string());
        row("pixels per clock", format!("{:.3}", self.pixels_per_clock));
        let mut out = format!("| {:<34} | {:>24} |\n|{}|{}|\n", "quantity", "value", "-".repeat(36), "-".repeat(26));
        out.push_str(&s);
        if let Some(w) = self.worst.first() {
            out.push_str(&format!(
                "worst pixel: ({}, {}) fixed {:?} float {:?} ({:.2} LSB)\n",
                w.x, w.y, w.fixed, w.reference, w.color_error
            ));
        }
        out
    }
}
