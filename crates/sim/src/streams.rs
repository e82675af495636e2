//! The model's transactions as port values, and back: a triangle (`[model::input::Vtx; 3]`,
//! and as the command parser hands it over, `model::command_parser::Triangle`),
//! a sorted triangle (`model::cull_sort::Sorted`), a set-up triangle
//! (`model::triangle_setup::TriangleSetupOut`), a span command (`model::edge_walk::SpanCmd`)
//! and a pixel (`model::span::Pixel`, also with an alpha and a blend mode) on the pins `<end>$<field>` of a link end, nested
//! fields joined by `_` (`inp$maj_at_c0`, `out$left_z`, `out$rgb2`). The fields and their
//! widths are read off the link's declaration (`rtl::links`), so a field the model does not
//! have, or a value that does not fit its port, fails here.

use crate::{Outputs, Value};
use model::command_parser::Triangle;
use model::cull_sort::Sorted;
use model::edge_walk::SpanCmd;
use model::input::Vtx;
use model::span::Pixel;
use model::triangle_setup::{Attrs, Edge, TriangleSetupOut, Walk};
use rtl::link::Link;
use rtl::links::{BlendPixelSink, ParsedSink, PixelSink, SortedSink, SpanCmdSink, TriangleSetupSink, TriangleSink};

/// Named port values, ready for `Dual::cycle` (through [`as_pins`]).
pub type PinValues = Vec<(String, Value)>;

/// `v` as a `width`-bit port value: two's complement when negative. Panics unless `v` fits
/// `width` bits as a signed or an unsigned number.
pub fn raw(width: usize, v: i128) -> Value {
    assert!(v >= -(1i128 << (width - 1)) && v < (1i128 << width), "{v} does not fit a {width}-bit port");
    Value::new(width, (v as u128) & (u128::MAX >> (128 - width)))
}

/// A port value read as a two's complement number.
pub fn signed(v: &Value) -> i128 {
    let w = v.width();
    fx::wrap_s(v.to_u128() as i128, w as u32)
}

/// A port value read as an unsigned number.
pub fn unsigned(v: &Value) -> u128 {
    v.to_u128()
}

/// Borrows named values as `Dual::cycle` takes them.
pub fn as_pins(values: &[(String, Value)]) -> Vec<(&str, Value)> {
    values.iter().map(|(n, v)| (n.as_str(), v.clone())).collect()
}

/// Field `field` of edge `e`: `j`, `count`, `x`, `r`, `q`, `rho`, `d`, or `at_`, `inc0_`,
/// `inc1_` and an attribute.
fn edge(e: &Edge, field: &str) -> i128 {
    match field.split_once('_') {
        None if field == "j" => e.j as i128,
        None if field == "count" => e.count as i128,
        None if field == "x" => e.x,
        None if field == "r" => e.r,
        None if field == "q" => e.q,
        None if field == "rho" => e.rho,
        None if field == "d" => e.d,
        Some(("at", f)) => attr(&e.at, f),
        Some(("inc0", f)) => attr(&e.inc0, f),
        Some(("inc1", f)) => attr(&e.inc1, f),
        _ => panic!("model::triangle_setup::Edge has no field {field}"),
    }
}

/// A set-up triangle on the pins of link end `end` (`edge_walk`'s `inp`:
/// `links::TriangleSetupSink`).
pub fn triangle_setup_out(end: &str, s: &TriangleSetupOut) -> PinValues {
    link_pins::<TriangleSetupSink>(end, |field| match field.split_once('_') {
        None if field == "walk" => (s.walk == Walk::Up) as i128,
        Some(("maj", "left")) => s.maj_left as i128,
        Some(("maj", f)) => edge(&s.maj, f),
        Some(("short0", f)) => edge(&s.short[0], f),
        Some(("short1", f)) => edge(&s.short[1], f),
        Some(("ddx", f)) => attr(&s.ddx, f),
        _ => panic!("model::triangle_setup::TriangleSetupOut has no field {field}"),
    })
}

/// Field `field` of attributes `a`: `z`, `c0`, `c1` or `c2`.
fn attr(a: &Attrs, field: &str) -> i128 {
    match field {
        "z" => a.z,
        "c0" => a.c[0],
        "c1" => a.c[1],
        "c2" => a.c[2],
        _ => panic!("model::triangle_setup::Attrs has no field {field}"),
    }
}

/// A span command on the pins of link end `end` (`span`'s `inp`: `links::SpanCmdSink`).
pub fn span_cmd(end: &str, c: &SpanCmd) -> PinValues {
    link_pins::<SpanCmdSink>(end, |field| match field.split_once('_') {
        None if field == "y" => c.y as i128,
        None if field == "xl" => c.xl,
        None if field == "xr" => c.xr,
        Some(("left", f)) => attr(&c.left, f),
        Some(("right", f)) => attr(&c.right, f),
        Some(("ddx", f)) => attr(&c.ddx, f),
        _ => panic!("model::edge_walk::SpanCmd has no field {field}"),
    })
}

fn attrs_of(o: &Outputs, name: &str) -> Attrs {
    Attrs { z: signed(o.get(&format!("{name}_z"))), c: std::array::from_fn(|i| signed(o.get(&format!("{name}_c{i}")))) }
}

/// The span command on the pins of link end `end` (`edge_walk`'s `out`: `links::SpanCmdSource`).
pub fn span_cmd_of(o: &Outputs, end: &str) -> SpanCmd {
    SpanCmd {
        y: unsigned(o.get(&format!("{end}$y"))) as i32,
        xl: signed(o.get(&format!("{end}$xl"))),
        xr: signed(o.get(&format!("{end}$xr"))),
        left: attrs_of(o, &format!("{end}$left")),
        right: attrs_of(o, &format!("{end}$right")),
        ddx: attrs_of(o, &format!("{end}$ddx")),
    }
}

/// The values of a link's fields on end `end` of a unit (pins `<end>$<field>`, each at the
/// link's width), `value` giving each field's value by name.
fn link_pins<L: Link>(end: &str, value: impl Fn(&str) -> i128) -> PinValues {
    L::FIELDS.iter().zip(L::WIDTHS).map(|(f, w)| (format!("{end}${f}"), raw(*w, value(f)))).collect()
}

/// Field `field` of pixel `p` (`x`, `y`, `z`, `rgb0`, `rgb1`, `rgb2`).
fn pixel_field(p: &Pixel, field: &str) -> i128 {
    match field {
        "x" => p.x as i128,
        "y" => p.y as i128,
        "z" => p.z as i128,
        "rgb0" => p.rgb[0] as i128,
        "rgb1" => p.rgb[1] as i128,
        "rgb2" => p.rgb[2] as i128,
        _ => panic!("model::span::Pixel has no field {field}"),
    }
}

/// A pixel on the pins of link end `end` (`pixel_out`'s `inp`: `links::PixelSink`).
pub fn pixel(end: &str, p: &Pixel) -> PinValues {
    link_pins::<PixelSink>(end, |field| pixel_field(p, field))
}

/// A pixel with its alpha and blend mode (`rtl::blend`'s code) on the pins of link end
/// `end` (the blending `pixel_out`'s `inp`: `links::BlendPixelSink`).
pub fn blend_pixel(end: &str, p: &Pixel, alpha: u8, mode: u8) -> PinValues {
    link_pins::<BlendPixelSink>(end, |field| match field {
        "alpha" => alpha as i128,
        "mode" => mode as i128,
        _ => pixel_field(p, field),
    })
}

/// The pixel on the pins of link end `end` (`span`'s `out`: `links::PixelSource`).
pub fn pixel_of(o: &Outputs, end: &str) -> Pixel {
    let get = |field: &str| unsigned(o.get(&format!("{end}${field}")));
    Pixel {
        x: get("x") as u32,
        y: get("y") as u32,
        z: get("z") as u32,
        rgb: std::array::from_fn(|i| get(&format!("rgb{i}")) as u8),
    }
}

/// Field `v<k>_<f>` of triangle `v` (`f`: `x`, `y`, `z`, `c0`, `c1`, `c2`, `iw`).
fn vertex(v: &[Vtx; 3], field: &str) -> Option<i128> {
    let (k, f) = field.strip_prefix('v')?.split_once('_')?;
    let v = v.get(k.parse::<usize>().ok()?)?;
    match f {
        "x" => Some(v.x),
        "y" => Some(v.y),
        "z" => Some(v.z),
        "c0" => Some(v.c[0]),
        "c1" => Some(v.c[1]),
        "c2" => Some(v.c[2]),
        "iw" => Some(v.iw),
        _ => None,
    }
}

/// A triangle on the pins of link end `end` (`cull_sort`'s `inp`: `links::TriangleSink`).
pub fn triangle(end: &str, v: &[Vtx; 3]) -> PinValues {
    link_pins::<TriangleSink>(end, |field| {
        vertex(v, field).unwrap_or_else(|| panic!("[model::input::Vtx; 3] has no field {field}"))
    })
}

/// A triangle as the command parser hands it over on the pins of link end `end`
/// (`links::ParsedSink`).
pub fn parsed(end: &str, t: &Triangle) -> PinValues {
    link_pins::<ParsedSink>(end, |field| match field {
        "end_of_buffer" => t.end_of_buffer as i128,
        "end_of_frame" => t.end_of_frame as i128,
        _ => {
            vertex(&t.vertices, field).unwrap_or_else(|| panic!("model::command_parser::Triangle has no field {field}"))
        }
    })
}

/// A sorted triangle on the pins of link end `end` (`triangle_setup`'s `inp`:
/// `links::SortedSink`).
pub fn sorted(end: &str, s: &Sorted) -> PinValues {
    link_pins::<SortedSink>(end, |field| match field {
        "crosses" => s.crosses as i128,
        _ => vertex(&s.v, field).unwrap_or_else(|| panic!("model::cull_sort::Sorted has no field {field}")),
    })
}
