//! The links between units, each declared once: a [`bundle!`](crate::bundle) of signals
//! with their directions (the memory port, `cull_sort`'s verdict), or a
//! [`link!`](crate::link), a valid/ready stream carrying one of the models' transactions,
//! field for field.
//!
//! A link declaration gives its two ends as rust-hdl interfaces: the sending unit's
//! (`valid` and every field out, `ready` in) and the receiving unit's (the opposite). A unit
//! holds an end as one field (`pub out: PixelSource`), its kernel reads and drives
//! `self.out.x`, a design connects two units with `PixelSource::join(&mut self.span.out,
//! &mut self.pixel_out.inp)` and passes its own port to a unit's with `PixelSink::link(&mut
//! self.inp, &mut self.pixel_out.inp)`. In the Verilog the ports are `<end>$<field>`
//! (`out$x`, `inp$valid`, `mem$rd_en`), as rust-hdl names an interface's signals; the
//! testbenches reach them by those names through [`LinkPins`], and convert the model's
//! transactions through [`Link::FIELDS`].

use crate::sim::Value;

/// One end of a link, by field name: what the simulators' pins need.
pub trait LinkPins {
    /// Drives input field `field`; `false` when this end has no such input.
    fn set(&mut self, field: &str, value: &Value) -> bool;
    /// Reads field `field` (an input or an output); `None` when there is none.
    fn get(&self, field: &str) -> Option<Value>;
}

/// What both ends of a link share: its fields, in declaration order.
pub trait Link {
    /// The fields (without `valid` and `ready`), in declaration order.
    const FIELDS: &'static [&'static str];
    /// Their widths in bits, in the same order.
    const WIDTHS: &'static [usize];
}

/// Whether signals of direction `D` are inputs of the unit holding them.
pub const fn is_input<D: rust_hdl::prelude::Direction>() -> bool {
    matches!(D::KIND, rust_hdl::prelude::AtomKind::InputParameter)
}

/// Declares a bundle: a rust-hdl interface of the signals given, each with its direction
/// (`In` or `Out`, as seen by the unit holding the bundle) and type (`Bit` or `Bits<N>`),
/// and its [`LinkPins`]; its widths may be const parameters (`Name<const A: usize> { ... }`).
#[macro_export]
macro_rules! bundle {
    (
        $(#[$meta:meta])*
        $name:ident $(< $(const $g:ident : usize),+ >)? {
            $( $(#[$fmeta:meta])* $dir:ident $field:ident : $ty:ty ),* $(,)?
        }
    ) => {
        $(#[$meta])*
        #[derive(LogicInterface, Default)]
        pub struct $name $(< $(const $g: usize),+ >)? {
            $( $(#[$fmeta])* pub $field: Signal<$dir, $ty>, )*
        }

        impl $(< $(const $g: usize),+ >)? $crate::link::LinkPins for $name $(< $($g),+ >)? {
            fn set(&mut self, field: &str, value: &$crate::sim::Value) -> bool {
                match field {
                    $( stringify!($field) if $crate::link::is_input::<$dir>() => {
                        self.$field.next = $crate::sim::PinValue::from_value(value)
                    } )*
                    _ => return false,
                }
                true
            }
            fn get(&self, field: &str) -> Option<$crate::sim::Value> {
                match field {
                    $( stringify!($field) => Some($crate::sim::PinValue::to_value(&self.$field.val())), )*
                    _ => None,
                }
            }
        }
    };
}

/// Declares a link: its two ends, `$source` and `$sink`, with the fields given (each a
/// `Bit` or `Bits<N>`), plus `valid` and `ready`. See the module's documentation.
#[macro_export]
macro_rules! link {
    // One end: a bundle with `valid` and `ready` in the directions given, and the fields
    // in direction `$d`.
    (@end $(#[$meta:meta])* $name:ident, $v:ident valid, $r:ident ready, $d:ident {
        $( $(#[$fmeta:meta])* $field:ident : $ty:ty ),*
    }) => {
        $crate::bundle! {
            $(#[$meta])*
            $name { $v valid: Bit, $r ready: Bit, $( $(#[$fmeta])* $d $field: $ty, )* }
        }
    };
    (
        $(#[$meta:meta])*
        $source:ident => $sink:ident {
            $( $(#[$fmeta:meta])* $field:ident : $ty:ty ),* $(,)?
        }
    ) => {
        $crate::link!(@end $(#[$meta])* #[doc = ""] #[doc = "The sending end: `valid` and the fields out, `ready` in."]
            $source, Out valid, In ready, Out { $( $(#[$fmeta])* $field: $ty ),* });
        $crate::link!(@end $(#[$meta])* #[doc = ""] #[doc = "The receiving end: `valid` and the fields in, `ready` out."]
            $sink, In valid, Out ready, In { $( $(#[$fmeta])* $field: $ty ),* });

        impl $source {
            /// Connects this end to `sink` (in a kernel: `Source::join(&mut a, &mut b)`).
            pub fn join(&mut self, sink: &mut $sink) {
                self.valid.join(&mut sink.valid);
                self.ready.join(&mut sink.ready);
                $( self.$field.join(&mut sink.$field); )*
            }
        }

        impl $crate::link::Link for $source {
            const FIELDS: &'static [&'static str] = &[$(stringify!($field)),*];
            const WIDTHS: &'static [usize] = &[$(<$ty as Synth>::BITS),*];
        }

        impl $crate::link::Link for $sink {
            const FIELDS: &'static [&'static str] = <$source as $crate::link::Link>::FIELDS;
            const WIDTHS: &'static [usize] = <$source as $crate::link::Link>::WIDTHS;
        }
    };
}

/// Joins the fields that two link ends of different links share, by name, with `valid` and
/// `ready`: in a kernel, `Shared::<ParsedSource, TriangleSink>::join(&mut self.parser.out,
/// &mut self.cull_sort.inp)` hands the parsed triangle's vertices to `cull_sort` and leaves
/// the end flags behind. Every field of `B` must be a field of `A`.
pub struct Shared<A, B>(std::marker::PhantomData<(A, B)>);

impl<A: LinkPins, B: LinkPins + Link> Shared<A, B> {
    /// The fields joined: `B`'s and `valid` from `a` to `b`, `ready` back.
    fn forward() -> impl Iterator<Item = &'static str> {
        B::FIELDS.iter().copied().chain(["valid"])
    }

    /// Rust's side (rust-hdl's simulation): drives `b`'s inputs from `a`'s outputs and back.
    pub fn join(a: &mut A, b: &mut B) {
        for f in Self::forward() {
            let v = a.get(f).unwrap_or_else(|| panic!("the link end joined has no field {f}"));
            assert!(b.set(f, &v), "{f} is not an input of the end joined to");
        }
        let ready = b.get("ready").expect("a link end has `ready`");
        assert!(a.set("ready", &ready), "`ready` is not an input of the sending end");
    }

    /// The Verilog's side: the same connections as `assign`s (rust-hdl's `join_hdl`).
    pub fn join_hdl(my_name: &str, this: &str, that: &str) -> Vec<rust_hdl::prelude::ast::VerilogLink> {
        use rust_hdl::prelude::ast::{VerilogLink, VerilogLinkDetails};
        let details = |f: &str| VerilogLinkDetails {
            my_name: format!("{my_name}.{f}"),
            owner_name: this.into(),
            other_name: that.into(),
        };
        let mut links: Vec<VerilogLink> = Self::forward().map(|f| VerilogLink::Forward(details(f))).collect();
        links.push(VerilogLink::Backward(details("ready")));
        links
    }
}
