//! edgepaint hardware units in rust-hdl, one file per unit, and their Verilog emission.
//!
//! [`UNITS`] is the one table of units: each name, with its parameters, builds and emits
//! the unit (`hdl-out/<name>.v`, top module `<name>`); its model is `model::<name>` and its
//! tests are `testbenches/tests/<name>.rs`. [`DEFAULT_DESIGN`] is what `edgepaint` with no
//! arguments writes into `hdl-out/`.

pub mod blend;
pub mod config;
pub mod emit;
pub mod ept;
pub mod link;
pub mod mul;
pub mod parts;
pub mod raster_top_textured;
pub mod se;
pub mod sim;
pub mod switch;
pub mod texture_address;
pub mod texture_cache;
pub mod texture_coords;
pub mod texture_filter;
pub mod texture_path;
pub mod texture_setup;
pub mod texture_unit;

/// The scanline pipeline's units, as modules of a build module (`n10.rs`, ..., `custom.rs`):
/// rust-hdl's widths are compile-time constants, so each build (`config`: a size class `n`,
/// screens up to 2^n x 2^n, and number formats, `CLASS` and `FORMATS` in the build module)
/// compiles its own copy of the same sources (`cull_sort.rs`, ..., `raster_top.rs`, and
/// `span_fifo.rs`, a part of `raster_top`), which read their widths from their build's
/// `widths` module. (Loading one file as several modules is the point here, hence the
/// `clippy::duplicate_mod` allowance.)
macro_rules! scanline_units {
    () => {
        #[path = "command_parser.rs"]
        pub mod command_parser;
        #[path = "cull_sort.rs"]
        pub mod cull_sort;
        #[path = "divider.rs"]
        pub mod divider;
        #[path = "edge_walk.rs"]
        pub mod edge_walk;
        #[path = "gpu_regs.rs"]
        pub mod gpu_regs;
        #[path = "gpu_top.rs"]
        pub mod gpu_top;
        #[path = "links.rs"]
        pub mod links;
        #[path = "pixel_bus.rs"]
        pub mod pixel_bus;
        #[path = "pixel_out.rs"]
        pub mod pixel_out;
        #[path = "raster_top.rs"]
        pub mod raster_top;
        #[path = "se_array.rs"]
        pub mod se_array;
        #[path = "se_cmd.rs"]
        pub mod se_cmd;
        #[path = "span.rs"]
        pub mod span;
        #[path = "span_fifo.rs"]
        pub mod span_fifo;
        #[path = "triangle_queue.rs"]
        pub mod triangle_queue;
        #[path = "triangle_setup.rs"]
        pub mod triangle_setup;
        #[path = "vector.rs"]
        pub mod vector;
        #[path = "widths.rs"]
        pub mod widths;
    };
}
#[allow(clippy::duplicate_mod)]
#[cfg(feature = "custom-formats")]
pub mod custom;
#[allow(clippy::duplicate_mod)]
pub mod n10;
#[allow(clippy::duplicate_mod)]
#[cfg(feature = "classes-11-12")]
pub mod n11;
#[allow(clippy::duplicate_mod)]
#[cfg(feature = "classes-11-12")]
pub mod n12;

/// Whether this edgepaint holds size classes 11 and 12 (the feature `classes-11-12`, on in
/// edgepaint's default features; without it they are `custom` builds made on demand).
const HOLDS_CLASSES_11_12: bool = cfg!(feature = "classes-11-12");

/// `rtl::custom`'s size class and where its formats came from, when this edgepaint holds it
/// (the feature `custom-formats`, on in edgepaint's default features; the test command
/// builds without it, and the soak with it).
pub const CUSTOM: Option<(u32, &str)> = {
    #[cfg(feature = "custom-formats")]
    let custom = Some((custom::CLASS, custom::SOURCE));
    #[cfg(not(feature = "custom-formats"))]
    let custom = None;
    custom
};

/// [`CUSTOM`] for messages: "and <source> at class <class>", or nothing.
fn custom_build_named() -> String {
    CUSTOM.map_or(String::new(), |(class, source)| format!(", and {source} at class {class}"))
}

/// The size classes the scanline units are built for at their default formats (`n10`, and
/// `n11` and `n12` with the feature `classes-11-12`).
pub const CLASSES: &[u32] = &[
    n10::CLASS,
    #[cfg(feature = "classes-11-12")]
    n11::CLASS,
    #[cfg(feature = "classes-11-12")]
    n12::CLASS,
];

/// Every build of the scanline units: the size classes at their default formats, then
/// `custom` when this edgepaint holds it.
pub const BUILDS: &[fx::Build] = &[
    fx::Build { class: n10::CLASS, formats: n10::FORMATS },
    #[cfg(feature = "classes-11-12")]
    fx::Build { class: n11::CLASS, formats: n11::FORMATS },
    #[cfg(feature = "classes-11-12")]
    fx::Build { class: n12::CLASS, formats: n12::FORMATS },
    #[cfg(feature = "custom-formats")]
    fx::Build { class: custom::CLASS, formats: custom::FORMATS },
];

/// Whether edgepaint holds a copy of the scanline units built at `build`.
pub fn built(build: &fx::Build) -> bool {
    BUILDS.contains(build)
}

/// A scanline unit's emitter: `$emit` of module `$unit` in the build of size class
/// `params["N"]` and the formats given (default: the class's).
macro_rules! by_build {
    ($unit:ident :: $emit:ident) => {
        |params: &Params, formats: Option<&Formats>| {
            emit_at_build(
                params,
                formats,
                stringify!($unit),
                [
                    n10::$unit::$emit,
                    #[cfg(feature = "classes-11-12")]
                    n11::$unit::$emit,
                    #[cfg(feature = "classes-11-12")]
                    n12::$unit::$emit,
                    #[cfg(feature = "custom-formats")]
                    custom::$unit::$emit,
                ],
            )
        }
    };
}

/// How a scanline unit of one build is emitted (its module's `emit_<unit>`).
type BuildEmitter = fn(&Params) -> Result<Emitted, String>;

/// `emit[i]` for `BUILDS[i]` = (`params["N"]`, `formats`); an error for a build
/// edgepaint does not hold.
fn emit_at_build(
    params: &Params,
    formats: Option<&Formats>,
    unit: &str,
    emit: [BuildEmitter; BUILDS.len()],
) -> Result<Emitted, String> {
    let n = params["N"];
    let Some(class) = u32::try_from(n).ok().filter(|c| BUILDS.iter().any(|b| b.class == *c)) else {
        let feature = if HOLDS_CLASSES_11_12 {
            ""
        } else {
            " (this edgepaint is built without the feature classes-11-12, on by default: classes 11 and 12 are \
             custom builds, which `edgepaint emit|render` compiles when asked)"
        };
        let custom = CUSTOM.map_or(String::new(), |(class, _)| format!(" and rtl::custom's {class}"));
        return Err(format!(
            "{unit}: N = {n} is not supported: size classes {CLASSES:?}{custom} (screens up to 2^N x 2^N){feature}"
        ));
    };
    let build = fx::Build { class, formats: formats.copied().unwrap_or(Formats::for_n(class)) };
    let i = BUILDS.iter().position(|b| *b == build).ok_or_else(|| {
        format!(
            "{unit}: edgepaint is not built at these formats for size class {class} (its builds: the defaults of \
             classes {CLASSES:?}{}); `edgepaint emit --formats FILE` rebuilds it",
            custom_build_named()
        )
    })?;
    let mut e = emit[i](params)?;
    e.formats = Some(build.formats);
    Ok(e)
}

/// The emitter of a unit without number formats (`ept`, `se`).
macro_rules! no_formats {
    ($unit:ident :: $emit:ident) => {
        |params: &Params, formats: Option<&Formats>| match formats {
            Some(_) => Err(format!("{} has no number formats to set", stringify!($unit))),
            None => $unit::$emit(params),
        }
    };
}

/// The default size class, [`fx::RTL_CLASS`] (screens up to 1024 x 1024): its units are
/// also at the crate's root (`rtl::raster_top`, ...).
pub use n10::{
    command_parser, cull_sort, divider, edge_walk, gpu_regs, gpu_top, links, pixel_bus, pixel_out, raster_top, se_cmd,
    span, triangle_queue, triangle_setup, vector, widths,
};
const _: () = assert!(n10::CLASS == fx::RTL_CLASS);

/// Multipliers in `triangle_setup` (and `raster_top`).
pub(crate) const K: Param = Param {
    name: "K",
    default: 7,
    doc: "triangle_setup's multipliers, 1 to 7 (latency 106 to 48, II 64 to 10, at L = 25); 001 has 7",
};
/// Stages of the shared divider (alone, in `triangle_setup` and in `raster_top`).
pub(crate) const L: Param = Param {
    name: "L",
    default: model::divider::LATENCY as u64,
    doc: "stages of the shared divider (latency), 1 to 32 (25: one quotient step a stage at class 10); 001 has 5",
};

/// The switches of the scanline units' optional parts (`switch::Parts`), each 1 (present)
/// by default.
const fn part(i: usize) -> Param {
    Param { name: switch::Parts::PARAMS[i].0, default: 1, doc: switch::Parts::PARAMS[i].1 }
}
const CULL: Param = part(0);
const CLIP_Y: Param = part(1);
const CLIP_X: Param = part(2);
const CLIP_Z: Param = part(3);
const DEPTH_TEST: Param = part(4);

/// Whether the vector unit's colours are perspective-correct.
const PERSPECTIVE: Param = Param {
    name: "PERSPECTIVE",
    default: 1,
    doc: "1: colours perspective-correct (004 eq. 5-6, the divider's second use); 0: screen-linear (vector)",
};

/// The vector unit's lanes.
const LANES: Param = Param {
    name: "LANES",
    default: 1,
    doc:
        "pixels per cycle of the vector unit (raster_top: with METHOD = 1): 1, 2, 4 or 8 lanes, a chunk of a row each cycle",
};

/// The SE back end's engine counts built (`raster_top`'s `ENGINES` with `METHOD = 2`), each
/// engine 64 columns of the screen (`rtl::se::SeWide`, P = 64).
pub const SE_ENGINES: [u32; 3] = [1, 5, 16];

/// The fewest engines built ([`SE_ENGINES`]) that cover a screen `width` columns wide;
/// `None` beyond 1,024 columns.
pub fn se_engines_for(width: u32) -> Option<u32> {
    SE_ENGINES.into_iter().find(|&e| 64 * e >= width)
}

/// The size-class parameter every scanline unit has.
const N: Param = Param {
    name: "N",
    default: fx::RTL_CLASS as u64,
    doc:
        "size class: screens up to 2^N x 2^N, formats Formats::for_n(N); 10, 11 or 12, or rtl::custom's class (8 to 12)",
};

use emit::Emitted;
use fx::Formats;
use std::collections::BTreeMap;

/// Parameter values of one unit by name, e.g. `{"P": 64}`.
pub type Params = BTreeMap<String, u64>;

/// One parameter of a unit.
#[derive(Debug)]
pub struct Param {
    pub name: &'static str,
    pub default: u64,
    /// What it means and which values are supported.
    pub doc: &'static str,
}

/// The texture units' level-of-detail rule (`texture_coords`, `texture_unit`,
/// `texture_path`).
const EXACT: Param =
    Param { name: "EXACT", default: 0, doc: "0: 001's eq. (4), max of the four derivatives; 1: GL's exact rho" };

/// [`EXACT`] of `unit` in `params`: whether GL's exact rho chooses the level.
pub fn exact_rule(unit: &str, params: &Params) -> Result<bool, String> {
    match params["EXACT"] {
        0 => Ok(false),
        1 => Ok(true),
        e => Err(format!("{unit}: EXACT = {e}: 0 (001's eq. 4) or 1 (GL's exact rho)")),
    }
}

/// One hardware unit: its name, parameters and how to emit it.
pub struct Unit {
    pub name: &'static str,
    /// One line: what the unit is and which paper and figure it follows.
    pub doc: &'static str,
    pub params: &'static [Param],
    /// Emits the unit for complete, named parameters and the formats given (`None`: the
    /// defaults); `Err` for unsupported values.
    build: Emitter,
}

/// How a unit is emitted for complete, named parameters and formats.
type Emitter = fn(&Params, Option<&Formats>) -> Result<Emitted, String>;

/// Every unit, by name.
pub const UNITS: &[Unit] = &[
    Unit {
        name: "ept",
        doc: "edge painting tree, paper 002 Figs. 2-5: pixel i painted iff XL <= i <= XR",
        params: &[Param { name: "P", default: 64, doc: "pixels per scanline, a power of two from 8 to 1024" }],
        build: no_formats!(ept::emit_ept),
    },
    Unit {
        name: "cull_sort",
        doc: "cull & sort, paper 003 Fig. 4, Table 1: outcodes, reject, back-face cull, sort by y; 1 cycle",
        params: &[N, CULL],
        build: by_build!(cull_sort::emit_cull_sort),
    },
    Unit {
        name: "divider",
        doc: "the shared pipelined floor divider of paper 001 §II.2: one division per cycle, exact",
        params: &[N, L],
        build: by_build!(divider::emit_divider),
    },
    Unit {
        name: "triangle_setup",
        doc: "triangle setup, paper 001 §II.2, eq. 2, Table 3: K multipliers reused, the 7 divisions on the shared divider",
        params: &[N, K, L],
        build: by_build!(triangle_setup::emit_triangle_setup),
    },
    Unit {
        name: "edge_walk",
        doc: "edge walk, papers 001 §II.2 and 003 Fig. 5: one scanline per cycle, exact edges, Y clipping",
        params: &[N, CLIP_Y],
        build: by_build!(edge_walk::emit_edge_walk),
    },
    Unit {
        name: "span",
        doc: "span unit, papers 001 §II.2 and 003 Fig. 6: one pixel per cycle, X and Z clipping",
        params: &[N, CLIP_X, CLIP_Z],
        build: by_build!(span::emit_span),
    },
    Unit {
        name: "pixel_out",
        doc: "depth test LESS and depth/colour writes through a synchronous memory port, one pixel (or chunk of LANES pixels) per cycle; BLEND = 1: the colour blended onto the colour read",
        params: &[
            N,
            DEPTH_TEST,
            Param {
                name: "LANES",
                default: 1,
                doc: "1: a pixel a cycle on the pixel link (inp), a memory word per pixel; 2, 4 or 8: a chunk of a row a cycle (in_*), a memory word per chunk",
            },
            Param {
                name: "BLEND",
                default: 0,
                doc: "0: the pixel's colour is written; 1 (LANES = 1): blended onto the colour read (mem$rd_rgb) by the pixel's alpha and mode (inp$alpha, inp$mode: blend's six modes, 001 §II.5, GL 4.6 §17.3.6), latency 2",
            },
        ],
        build: by_build!(pixel_out::emit_pixel_out),
    },
    Unit {
        name: "se_cmd",
        doc: "the SE back end's span command unit (000 Fig. 5): a span's lines A X + B for the engines, x0 A a bit a cycle, issued at the engines' gap",
        params: &[N],
        build: by_build!(se_cmd::emit_se_cmd),
    },
    Unit {
        name: "gpu_regs",
        doc: "gpu_top's register block on an AXI4-Lite slave: control, status, interrupt, buffer addresses (model::gpu_regs::Reg)",
        params: &[N],
        build: by_build!(gpu_regs::emit_gpu_regs),
    },
    Unit {
        name: "pixel_bus",
        doc: "pixel_out on AXI4: the depth test and the depth and colour buffers in system memory, a clear, 16 pixels in flight",
        params: &[N],
        build: by_build!(pixel_bus::emit_pixel_bus),
    },
    Unit {
        name: "command_parser",
        doc: "command parser, paper 001 Fig. 4: a vertex buffer's header, index and vertex records over AXI4, a vertex cache",
        params: &[
            N,
            Param {
                name: "CACHE",
                default: 512,
                doc: "vertex cache entries, 16, 64, 256, 512 or 1024 (model::command_parser::Params::cache)",
            },
        ],
        build: by_build!(command_parser::emit_command_parser),
    },
    Unit {
        name: "triangle_queue",
        doc: "the triangles between command_parser and cull_sort in gpu_top, in block RAM: the parser runs ahead of the rasterizer",
        params: &[
            N,
            Param {
                name: "DEPTH",
                default: 512,
                doc: "triangles queued, 4, 64, 256 or 512 (model::triangle_queue::TriangleQueue::new)",
            },
        ],
        build: by_build!(triangle_queue::emit_triangle_queue),
    },
    Unit {
        name: "raster_top",
        doc: "the scanline rasterizer of papers 001 and 003: cull_sort, setup with the divider, edge walk, span, pixel out",
        params: &[
            N,
            K,
            L,
            Param {
                name: "CULL_SORT",
                default: 1,
                doc: "1: cull_sort present; 0: absent, sorted triangles with their clip crossings in (the link inp, inp$crosses)",
            },
            Param {
                name: "PIXEL_OUT",
                default: 1,
                doc: "1: pixel_out and its memory port present; 0: absent, the fragment stream out (out_*)",
            },
            CULL,
            CLIP_Y,
            CLIP_X,
            CLIP_Z,
            DEPTH_TEST,
            Param {
                name: "METHOD",
                default: 0,
                doc: "0: the scanline method (001, 003); 1: the barycentric method (004): cull_sort, vector, pixel_out (K unused); 2: the SE back end (000): the scanline front end, se_cmd and ENGINES shading engines",
            },
            PERSPECTIVE,
            LANES,
            Param {
                name: "ENGINES",
                default: 16,
                doc: "the SE back end's shading engines (METHOD = 2): 1, 5 or 16, screens up to 64 columns a engine",
            },
            Param {
                name: "TEXTURE",
                default: 0,
                doc: "1: textured (N = 10, METHOD = 0): texture_path between span and a blending pixel_out, the texture words on tex$* and tex_state$*, the texture memory on tex_mem$*, the cache's counters on counters$*",
            },
            EXACT,
        ],
        build: by_build!(raster_top::emit_raster_top),
    },
    Unit {
        name: "gpu_top",
        doc: "edgepaint as a core: gpu_regs (AXI4-Lite), command_parser (AXI4 reads), the scanline rasterizer, pixel_bus (AXI4)",
        params: &[N, K, L],
        build: by_build!(gpu_top::emit_gpu_top),
    },
    Unit {
        name: "vector",
        doc: "per-pixel barycentric rasterization, paper 004 eq. 1-6: LANES pixels per cycle, a walk of each row's chunks, perspective-correct colours",
        params: &[
            N,
            L,
            PERSPECTIVE,
            LANES,
        ],
        build: by_build!(vector::emit_vector),
    },
    Unit {
        name: "se",
        doc: "shading engine, paper 000 Figs. 6-10: serial multipliers, bit-serial interpolator, EPT mask, z compare, 4 ports",
        params: &[
            Param { name: "P", default: 64, doc: "pixels per engine (region width): 8, 16, 32 or 64" },
            Param { name: "ZW", default: 24, doc: "bits of a z word (000: 24)" },
            Param { name: "CW", default: 16, doc: "bits of a colour word (000: 16)" },
            Param { name: "F", default: 16, doc: "fraction bits of the lines' A and B" },
            Param { name: "I", default: 0, doc: "engine index i: region [P i, P (i + 1)), P (i + 1) < 2048" },
        ],
        build: no_formats!(se::emit_se),
    },
    Unit {
        name: "texture_address",
        doc: "the texture unit's addresses, paper 001 §II.5 / GL 4.6 §8.14: level, 2x2 footprint, wrap, a word per cache bank; combinational",
        params: &[],
        build: no_formats!(texture_address::emit_texture_address),
    },
    Unit {
        name: "texture_coords",
        doc: "the texture unit's coordinates, paper 001 §II.5 eq. (3) and (4): s = (s·q)/q, t likewise, lambda; a pixel a clock",
        params: &[EXACT],
        build: no_formats!(texture_coords::emit_texture_coords),
    },
    Unit {
        name: "texture_cache",
        doc: "the texture cache of paper 001 §II.5 (printed §II.2.마): four banks (a 2x2 bilinear footprint a clock), one memory read port",
        params: &[
            Param {
                name: "SETS",
                default: 64,
                doc: "sets per bank, a power of two from 4 to 256 (built: rtl::texture_cache::GEOMETRIES)",
            },
            Param { name: "WAYS", default: 2, doc: "lines per set: 1, 2 or 4 (round-robin replacement per set)" },
            Param { name: "LINE", default: 4, doc: "32-bit words per line, a power of two from 1 to 16" },
        ],
        build: no_formats!(texture_cache::emit_texture_cache),
    },
    Unit {
        name: "texture_filter",
        doc: "the texture unit's filter, paper 001 §II.5, Fig. 6: decode, bilinear (linear or Gaussian weights), levels, environment; a pixel a clock",
        params: &[],
        build: no_formats!(texture_filter::emit_texture_filter),
    },
    Unit {
        name: "texture_setup",
        doc: "paper 001 §II.5's texture planes: per triangle the gradients of s·q, t·q, q (one shared multiplier, 30 cycles) and the LOD gradients; per pixel s·q, t·q, q, a pixel a clock",
        params: &[],
        build: no_formats!(texture_setup::emit_texture_setup),
    },
    Unit {
        name: "blend",
        doc: "framebuffer blending, paper 001 §II.5's six blend modes as GL 4.6 §17.3.6 blend functions: src RGBA8 onto dst RGBA8, products rounded exactly (x y / 255), saturating adds; combinational",
        params: &[],
        build: no_formats!(blend::emit_blend),
    },
    Unit {
        name: "texture_unit",
        doc: "paper 001 §II.5's texture unit, one pipeline: texture_coords, texture_address, texture_cache, texture_filter; a pixel a clock while the cache hits, stalls on a miss",
        params: &[
            Param { name: "SETS", default: 64, doc: "the cache's sets per bank (built: rtl::texture_unit::GEOMETRIES)" },
            Param { name: "WAYS", default: 2, doc: "the cache's lines per set" },
            Param { name: "LINE", default: 4, doc: "the cache's 32-bit words per line" },
            EXACT,
        ],
        build: no_formats!(texture_unit::emit_texture_unit),
    },
    Unit {
        name: "texture_path",
        doc: "a textured fragment's way, paper 001 §II.5: per triangle texture_setup (on its first fragment, 30 cycles), per fragment texture_setup's pixel part and texture_unit (the default cache); out: the blending pixel_out's fragments",
        params: &[EXACT],
        build: no_formats!(texture_path::emit_texture_path),
    },
];

/// The default design: units and parameters that `edgepaint` with no arguments emits.
pub const DEFAULT_DESIGN: &[(&str, &[(&str, u64)])] = &[
    ("ept", &[("P", 64)]),
    ("cull_sort", &[("N", 10), ("CULL", 1)]),
    ("divider", &[("N", 10), ("L", model::divider::LATENCY as u64)]),
    ("triangle_setup", &[("N", 10), ("K", 7), ("L", model::divider::LATENCY as u64)]),
    ("edge_walk", &[("N", 10), ("CLIP_Y", 1)]),
    ("span", &[("N", 10), ("CLIP_X", 1), ("CLIP_Z", 1)]),
    ("pixel_out", &[("N", 10), ("DEPTH_TEST", 1), ("LANES", 1), ("BLEND", 0)]),
    ("se_cmd", &[("N", 10)]),
    ("pixel_bus", &[("N", 10)]),
    ("gpu_regs", &[("N", 10)]),
    ("command_parser", &[("N", 10), ("CACHE", 512)]),
    ("triangle_queue", &[("N", 10), ("DEPTH", 512)]),
    ("texture_coords", &[("EXACT", 0)]),
    ("texture_address", &[]),
    ("texture_cache", &[("SETS", 64), ("WAYS", 2), ("LINE", 4)]),
    ("texture_filter", &[]),
    ("texture_setup", &[]),
    ("blend", &[]),
    ("texture_unit", &[("SETS", 64), ("WAYS", 2), ("LINE", 4), ("EXACT", 0)]),
    ("texture_path", &[("EXACT", 0)]),
    (
        "raster_top",
        &[
            ("N", 10),
            ("K", 7),
            ("L", model::divider::LATENCY as u64),
            ("CULL_SORT", 1),
            ("PIXEL_OUT", 1),
            ("CULL", 1),
            ("CLIP_Y", 1),
            ("CLIP_X", 1),
            ("CLIP_Z", 1),
            ("DEPTH_TEST", 1),
            ("METHOD", 0),
            ("PERSPECTIVE", 1),
            ("LANES", 1),
            ("ENGINES", 16),
            ("TEXTURE", 0),
            ("EXACT", 0),
        ],
    ),
    ("gpu_top", &[("N", 10), ("K", 7), ("L", model::divider::LATENCY as u64)]),
    ("vector", &[("N", 10), ("L", model::divider::LATENCY as u64), ("PERSPECTIVE", 1), ("LANES", 1)]),
    ("se", &[("P", 64), ("ZW", 24), ("CW", 16), ("F", 16), ("I", 0)]),
];

/// Builds beside the default design that `edgepaint` with no arguments also emits, each
/// into a directory of `hdl-out/` named after the parameters it sets
/// (`raster_top-METHOD=1-LANES=4/raster_top.v`): `raster_top` with the barycentric back end
/// at four lanes, and with the SE back end (16 engines), each a whole pipeline with the
/// default `raster_top`'s ports but its memory port; and the textured `raster_top`
/// (`rtl::raster_top_textured`). The parameters are set over the unit's in
/// [`DEFAULT_DESIGN`].
pub const DEFAULT_VARIANTS: &[(&str, &[(&str, u64)])] = &[
    ("raster_top", &[("METHOD", 1), ("LANES", 4)]),
    ("raster_top", &[("METHOD", 2)]),
    ("raster_top", &[("TEXTURE", 1)]),
];

impl Unit {
    /// The unit called `name`.
    pub fn named(name: &str) -> Option<&'static Unit> {
        UNITS.iter().find(|u| u.name == name)
    }

    /// `given` over the defaults; `Err` names an unknown parameter.
    pub fn params(&self, given: impl IntoIterator<Item = (String, u64)>) -> Result<Params, String> {
        let mut out: Params = self.params.iter().map(|p| (p.name.to_owned(), p.default)).collect();
        for (k, v) in given {
            if !out.contains_key(&k) {
                let known: Vec<_> = self.params.iter().map(|p| p.name).collect();
                return Err(format!("unit {} has no parameter {k} (it has: {})", self.name, known.join(", ")));
            }
            out.insert(k, v);
        }
        Ok(out)
    }

    /// Emits the unit with `params` (complete: see [`Unit::params`]) at its default formats.
    pub fn emit(&self, params: &Params) -> Result<Emitted, String> {
        (self.build)(params, None)
    }

    /// Emits the unit with `params` at `formats` (a scanline unit: one of [`BUILDS`] at
    /// size class `params["N"]`).
    pub fn emit_at(&self, params: &Params, formats: &Formats) -> Result<Emitted, String> {
        (self.build)(params, Some(formats))
    }
}
