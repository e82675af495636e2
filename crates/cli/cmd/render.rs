//! `edgepaint render`: scene or trilist -> PNG, through one of the engines.

use super::engine::{Engine, FixedArgs};
use super::input::{self, Size};
use anyhow::{Context, Result};
use image::{ImageBuffer, Luma, Rgb};
use indicatif::{ProgressBar, ProgressStyle};
use reference::{Cull, Options};
use std::io::Cursor;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Arguments of `edgepaint render`.
#[derive(clap::Args)]
pub struct Args {
    /// Scene file or trilist (JSON; told apart by their keys), or vertex buffer
    /// (`edgepaint pack`; drawn at the formats in its header).
    input: PathBuf,
    /// Output PNG (8-bit RGB).
    #[arg(short, long)]
    output: PathBuf,
    /// Also write depth as a 16-bit grey PNG (round(z * 65535); 65535 where nothing was drawn).
    #[arg(long)]
    depth: Option<PathBuf>,
    /// Also write the coverage mask as an 8-bit PNG (255 where a triangle wrote the pixel).
    #[arg(long)]
    mask: Option<PathBuf>,
    /// Face culling; a scene's own "cull" setting is the default.
    #[arg(long, value_enum)]
    cull: Option<CullArg>,
    /// Interpolate colour screen-linearly even when the input carries w.
    #[arg(long)]
    linear: bool,
    /// Override a scene's resolution, e.g. 320x240.
    #[arg(long)]
    size: Option<Size>,
    /// Which rasterizer draws.
    #[arg(long, value_enum, default_value = "float")]
    engine: Engine,
    #[command(flatten)]
    fixed: FixedArgs,
    /// Fixed-point engines: check every triangle for harmful overflow and draw
    /// only those without (reported), instead of drawing as the hardware would.
    #[arg(long)]
    analysis: bool,
    /// `--engine rtl`: a parameter of raster_top, `K=<1..7>` (setup's multipliers),
    /// `L=<1..25>` (the divider's stages), `N=<class>` (the size class, default the
    /// screen's) or an optional part's switch (`CLIP_Y=0`, ...: `rtl::switch`, README "Fit"); repeatable.
    #[arg(long = "param", value_name = "NAME=VALUE", value_parser = super::emit::parse_param)]
    params: Vec<(String, u64)>,
    /// `--engine rtl`: the top that draws: `gpu_top` (the scene packed into a vertex buffer
    /// in memory, the core driven through its registers and bus ports; the default build
    /// only, no --param) or `raster_top` (triangles on the scanline pipeline's ports; any
    /// size class, formats and --param). Default: gpu_top where it applies.
    #[arg(long, value_enum)]
    top: Option<super::rtl::Top>,
    /// `--engine rtl`: raster_top's method: `scanline` (001, 003; the default), `vector`
    /// (004: cull_sort, the per-pixel barycentric unit with --lanes lanes, pixel_out; colours
    /// perspective-correct unless --linear) or `se` (000's shading engines behind the scanline
    /// front end; --param ENGINES=1, 5 or 16, default the fewest that cover the screen).
    #[arg(long, value_enum)]
    method: Option<super::rtl::RtlMethod>,
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum CullArg {
    None,
    Back,
}

/// One rendered image in the form the PNG writers take.
pub struct Image {
    pub width: u32,
    pub height: u32,
    pub rgb: Vec<[u8; 3]>,
    pub depth16: Vec<u16>,
    pub written: Vec<bool>,
}

pub fn run(args: Args) -> Result<()> {
    let loaded = input::load(&args.input, args.size)?;
    if args.engine == Engine::Se && (loaded.trilist.is_textured() || loaded.trilist.is_blended()) {
        anyhow::bail!(
            "{}: the scene is textured or blends, and --engine se cannot texture or blend: 000's shading \
             engines interpolate colour and write it inside their pixel memories, with no per-pixel path \
             out to a texture unit or a blender (README, \"The texture unit\"); draw it with --engine \
             scanline or vector",
            args.input.display()
        );
    }
    let list = &loaded.trilist;
    let cull_back = match args.cull {
        Some(CullArg::Back) => true,
        Some(CullArg::None) => false,
        None => loaded.cull_back,
    };
    let opts = Options {
        cull: if cull_back { Cull::Back } else { Cull::None },
        ignore_w: args.linear,
        background: loaded.background,
    };

    if args.engine == Engine::Se {
        return se(&args, list, &args.fixed.formats_of(&loaded)?, cull_back, loaded.background);
    }

    let bar = ProgressBar::new(list.triangles.len() as u64);
    bar.set_style(ProgressStyle::with_template("{msg} {bar:40} {pos}/{len} triangles").expect("static template"));
    bar.set_message("render");
    let mut progress = |done: usize| bar.set_position(done as u64);
    let start = Instant::now();
    let perspective = !args.linear;
    anyhow::ensure!(
        args.params.is_empty() || args.engine == Engine::Rtl,
        "--param sets raster_top's parameters: it needs --engine rtl"
    );
    anyhow::ensure!(
        args.top.is_none() || args.engine == Engine::Rtl,
        "--top picks the RTL's top: it needs --engine rtl"
    );
    anyhow::ensure!(
        args.method.is_none() || args.engine == Engine::Rtl,
        "--method picks the RTL's method: it needs --engine rtl (the models' methods are engines: --engine vector)"
    );
    let (image, summary) = match args.fixed.method(args.engine, perspective)? {
        _ if args.engine == Engine::Rtl => {
            let how = super::rtl::How {
                method: args.method.unwrap_or(super::rtl::RtlMethod::Scanline),
                perspective,
                params: &args.params,
                top: args.top,
                input: &args.input,
            };
            match super::rtl::render(&loaded, cull_back, &args.fixed, args.analysis, &how)? {
                Some(drawn) => drawn,
                None => return Ok(()), // drawn by an edgepaint compiled at --formats
            }
        }
        None => {
            let (frame, stats) = reference::render(list, &opts, &mut progress);
            let image = Image {
                width: frame.width,
                height: frame.height,
                rgb: frame.rgb8(),
                depth16: frame.depth16(),
                written: frame.written,
            };
            let summary = format!(
                "float reference: {} triangles in, {} drawn, {} culled ({} back-facing, {} degenerate); {} fragments, {} z-clipped, {} pixels written",
                stats.triangles_in, stats.drawn, stats.culled(), stats.culled_back, stats.degenerate, stats.fragments, stats.z_clipped, stats.pixels_written
            );
            (image, (summary, stats.fragments))
        }
        Some(method) => {
            let f = args.fixed.formats_of(&loaded)?;
            let mopts = model::render::Options {
                method,
                cull: if cull_back { model::cull_sort::Cull::Back } else { model::cull_sort::Cull::None },
                analysis: args.analysis,
                background: loaded.background.map(|c| c.round().clamp(0.0, 255.0) as u8),
            };
            let texturing = args.fixed.texturing(list, args.linear, &args.input)?;
            let r = model::render::render_with(list, &f, &mopts, texturing.as_ref(), &mut progress);
            for p in r.problems.iter().take(5) {
                eprintln!("warning: triangle {} not drawn: {}", p.triangle, problem(&p.why));
            }
            if r.problems.len() > 5 {
                eprintln!("warning: ... {} triangles in all not drawn", r.problems.len());
            }
            let cycles = match method {
                model::render::Method::Scanline => model::cycles::scanline_frame(&r.work, &Default::default()),
                model::render::Method::Vector { .. } => model::cycles::vector_frame(&r.work, &Default::default()),
            };
            let st = &r.stats;
            let summary = format!(
                "{} (fixed point): {} triangles in, {} drawn, {} culled ({} outside, {} back-facing, {} degenerate), {} not drawn (input or overflow); {} spans, {} fragments, {} z-clipped, {} pixels written; predicted {} cycles, {:.3} pixels per clock",
                accuracy::method_name(method), st.triangles_in, st.drawn, st.culled_outside + st.culled_back + st.degenerate, st.culled_outside, st.culled_back, st.degenerate,
                st.input_rejected + st.overflowed, st.spans, st.fragments, st.z_clipped, st.pixels_written, cycles.total,
                st.pixels_written as f64 / cycles.total.max(1) as f64
            );
            let summary = match &texturing {
                None => summary,
                Some(_) => {
                    let c = accuracy::texture::cache_stats(&accuracy::texture::DEFAULT_CACHE, &r.fetches);
                    format!(
                        "{summary}; texture cache ({} sets, {} ways, {} words): {} accesses (2x2 footprints), hit rate {:.4}",
                        c.sets,
                        c.ways,
                        c.line,
                        r.fetches.len(),
                        c.hit_rate
                    )
                }
            };
            let depth16 = r.fb.depth.iter().map(|&d| depth16(d, f.z.frac)).collect();
            let image = Image { width: r.fb.width, height: r.fb.height, rgb: r.fb.rgb, depth16, written: r.fb.written };
            (image, (summary, st.fragments))
        }
    };
    let elapsed = start.elapsed();
    bar.finish_and_clear();

    write_outputs(&image, &args.output, args.depth.as_deref(), args.mask.as_deref())?;
    let secs = elapsed.as_secs_f64();
    println!(
        "render {}; {:.2} ms ({:.1} Mfragment/s, {:.1} Mpixel/s of {}x{} screen)",
        summary.0,
        secs * 1e3,
        summary.1 as f64 / secs / 1e6,
        (list.width as f64 * list.height as f64) / secs / 1e6,
        list.width,
        list.height,
    );
    Ok(())
}

/// `--engine se`: the scanline pipeline's spans drawn by 000's shading engines, one per
/// 64 columns (`model::se::array`); prints the engines' cycles per span and per frame, and
/// the whole SE back end's frame (`raster_top` with `METHOD = 2`).
fn se(args: &Args, list: &scene::Trilist, f: &fx::Formats, cull_back: bool, background: [f64; 3]) -> Result<()> {
    anyhow::ensure!(!args.analysis, "--analysis applies to --engine scanline and vector, not se");
    let cull = if cull_back { model::cull_sort::Cull::Back } else { model::cull_sort::Cull::None };
    let bg = background.map(|c| c.round().clamp(0.0, 255.0) as u8);
    let start = Instant::now();
    let r = model::se::array::render(list, f, cull, bg).map_err(|e| anyhow::anyhow!(e))?;
    let secs = start.elapsed().as_secs_f64();
    let whole =
        model::se::array::back_end_cycles(list, f, cull, bg, &Default::default()).map_err(|e| anyhow::anyhow!(e))?;
    let depth16 = r.fb.depth.iter().map(|&d| depth16(d, f.z.frac)).collect();
    let image = Image { width: r.fb.width, height: r.fb.height, rgb: r.fb.rgb, depth16, written: r.fb.written };
    write_outputs(&image, &args.output, args.depth.as_deref(), args.mask.as_deref())?;
    let (st, prm) = (&r.stats, model::se::array::engine_params(f));
    println!(
        "render se (000 shading engines: {} x {} pixels, z/colour words {}/{} bits): {} triangles in, {} drawn, {} culled ({} outside, {} back-facing, {} degenerate), {} not drawn (input); {} spans, {} pixels written; {} cycles, {:.1} per span ({} per span back to back, {} after a span on the same row: {} such), {} spans overflowed; the whole back end (raster_top METHOD = 2, model::cycles::se_frame): {} cycles; {:.2} ms",
        r.engines, prm.p, prm.zw, prm.cw, st.triangles_in, st.drawn, st.culled_outside + st.culled_back + st.degenerate,
        st.culled_outside, st.culled_back, st.degenerate, st.input_rejected, st.spans, r.pixels_written, r.cycles,
        r.cycles as f64 / st.spans.max(1) as f64, prm.ii(), prm.latency(), r.same_row_stalls, r.ends_overflowed, whole, secs * 1e3,
    );
    Ok(())
}

/// A depth-buffer value with `frac` bits as a 16-bit PNG sample (its top 16
/// bits, or scaled up when the buffer is narrower).
pub fn depth16(d: u32, frac: u32) -> u16 {
    if frac >= 16 {
        (d >> (frac - 16)) as u16
    } else {
        (d << (16 - frac)) as u16
    }
}

/// Why a triangle was not drawn, in words.
fn problem(why: &model::render::Dropped) -> String {
    match why {
        model::render::Dropped::Input(e) => e.to_string(),
        model::render::Dropped::Overflow(q) => {
            let names: Vec<&str> = q.iter().map(|q| q.name()).collect();
            format!("harmful overflow in {}", names.join(", "))
        }
        model::render::Dropped::Rejected(r) => format!("{r:?}"),
    }
}

/// Writes the colour PNG and, when asked, the depth and mask PNGs.
pub fn write_outputs(img: &Image, output: &Path, depth: Option<&Path>, mask: Option<&Path>) -> Result<()> {
    let (w, h) = (img.width, img.height);
    let rgb: ImageBuffer<Rgb<u8>, Vec<u8>> =
        ImageBuffer::from_raw(w, h, img.rgb.iter().flatten().copied().collect()).context("colour buffer size")?;
    save(output, "the image", &rgb)?;
    if let Some(path) = depth {
        let d: ImageBuffer<Luma<u16>, Vec<u16>> =
            ImageBuffer::from_raw(w, h, img.depth16.clone()).context("depth buffer size")?;
        save(path, "the depth image", &d)?;
    }
    if let Some(path) = mask {
        let m: ImageBuffer<Luma<u8>, Vec<u8>> =
            ImageBuffer::from_raw(w, h, img.written.iter().map(|&b| if b { 255 } else { 0 }).collect())
                .context("mask size")?;
        save(path, "the coverage mask", &m)?;
    }
    Ok(())
}

fn save<P: image::Pixel<Subpixel = S> + image::PixelWithColorType, S: image::Primitive>(
    path: &Path,
    what: &str,
    img: &ImageBuffer<P, Vec<S>>,
) -> Result<()>
where
    [S]: image::EncodableLayout,
{
    let mut bytes = Vec::new();
    img.write_to(&mut Cursor::new(&mut bytes), image::ImageFormat::Png).with_context(|| format!("encoding {what}"))?;
    input::write(path, what, &bytes)
}
