//! The rtl crate's own tests (one binary: each test binary links rust-hdl and every build
//! of the units): its parts, the emission, `hdl-out/`'s freshness and the widths of each
//! size class. The units themselves are tested against their models in `testbenches/`.

mod parts {
    use rtl::parts::*;
    use rtl::sim::settle;
    use rust_hdl::prelude::*;

    #[test]
    fn parts_signed_exhaustive_n5() {
        let (mut neg, mut less) = (Negative::<5>::default(), SignedLess::<5>::default());
        neg.connect_all();
        less.connect_all();
        let raw = |v: i64| bits::<5>((v & 31) as u64);
        for a in -16i64..16 {
            neg.x.next = raw(a);
            settle(&mut neg);
            assert_eq!(neg.neg.val(), a < 0, "a={a}");
            for b in -16i64..16 {
                less.a.next = raw(a);
                less.b.next = raw(b);
                settle(&mut less);
                assert_eq!(less.lt.val(), a < b, "a={a} b={b}");
            }
        }
    }

    #[test]
    fn parts_round_shift_is_shr_half_up_exhaustive_in6() {
        // 6-bit x, 2 fraction bits, 2-bit result: every value, with both range flags.
        let mut u = RoundShift::<6, 7, 2, 2>::default();
        u.connect_all();
        for x in -32i128..32 {
            u.x.next = bits::<6>((x & 63) as u64);
            settle(&mut u);
            let r = fx::shr_half_up(x, 2);
            assert_eq!((u.neg.val(), u.over.val()), (r < 0, r >= 4), "x={x}");
            if (0..4).contains(&r) {
                assert_eq!(u.low.val(), bits::<2>(r as u64), "x={x}");
            }
        }
    }

    #[test]
    fn parts_round_range_is_round_shifts_flags_exhaustive_in6() {
        // 6-bit x, 2 fraction bits: a 2-bit result (2^(S+OUT) well inside x's range), a
        // 3-bit one (at its top) and a 4-bit one (no x rounds to 16 or more).
        fn check<const OUT: usize>(mut u: RoundRange<6, OUT, 2>) {
            u.connect_all();
            for x in -32i128..32 {
                u.x.next = bits::<6>((x & 63) as u64);
                settle(&mut u);
                let r = fx::shr_half_up(x, 2);
                assert_eq!((u.neg.val(), u.over.val()), (r < 0, r >= 1 << OUT), "OUT={OUT} x={x}");
            }
        }
        check::<2>(RoundRange::default());
        check::<3>(RoundRange::default());
        check::<4>(RoundRange::default());
    }

    #[test]
    fn parts_concat_puts_hi_above_lo() {
        let mut u = Concat::<3, 5, 8>::default();
        u.connect_all();
        u.hi.next = bits(0b101);
        u.lo.next = bits(0b0_0110);
        settle(&mut u);
        assert_eq!(u.out.val(), bits::<8>(0b1010_0110));
    }
}

mod mul {
    use rtl::mul::*;
    use rtl::sim::settle;
    use rust_hdl::prelude::*;

    #[test]
    fn mul_exhaustive_4x3_into_5_bits_wraps_like_verilog() {
        let mut m = Mul::<4, 3, 5>::default();
        m.connect_all();
        for a in -8i64..8 {
            for b in -4i64..4 {
                m.a.next = bits((a & 15) as u64);
                m.b.next = bits((b & 7) as u64);
                settle(&mut m);
                assert_eq!(m.p.val().to_u64(), ((a * b) & 31) as u64, "a={a} b={b}");
            }
        }
    }
}

mod sim {
    use rtl::sim::*;
    use rust_hdl::prelude::*;

    #[test]
    fn value_round_trips_through_wide_bits() {
        let words = [0x0123_4567_89ab_cdef, 0xfedc_ba98_7654_3210, 0x5];
        let v = Value::from_words(130, &words);
        let b: Bits<130> = v.to_bits();
        assert!(b.get_bit(0) && b.get_bit(128) && !b.get_bit(129));
        assert_eq!(Value::from_bits(b), v);
        assert_eq!(Value::from_bits::<6>(v.to_bits::<130>().get_bits::<6>(0)), Value::new(6, 0x2f));
    }

    #[test]
    fn value_prints_like_verilog() {
        assert_eq!(Value::new(6, 0x2a).to_string(), "6'h2a");
        assert_eq!(Value::new(1, 1).to_string(), "1'h1");
        assert_eq!(Value::from_words(72, &[u64::MAX, 0x3]).to_string(), "72'h03_ffff_ffff_ffff_ffff");
    }
}

mod emit {
    use rtl::emit::*;
    use rtl::sim::PortDir;
    use rtl::{Unit, UNITS};
    use std::path::{Path, PathBuf};

    fn repo() -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
    }

    /// `hdl-out/` is committed: it must be exactly what `edgepaint` emits now.
    #[test]
    fn hdl_out_is_fresh() {
        let dir = repo().join("hdl-out");
        let files = files(&default_design());
        for (name, text) in &files {
            let committed = std::fs::read_to_string(dir.join(name)).unwrap_or_default();
            assert!(
                committed == *text,
                "hdl-out/{name} is stale or missing: run `cargo run --release` and commit hdl-out/"
            );
        }
        let mut dirs = vec![dir.clone()];
        while let Some(at) = dirs.pop() {
            for entry in std::fs::read_dir(&at).expect("hdl-out/") {
                let path = entry.expect("hdl-out/ entry").path();
                if path.is_dir() {
                    dirs.push(path);
                    continue;
                }
                let name = path.strip_prefix(&dir).expect("under hdl-out/").to_string_lossy().into_owned();
                assert!(
                    files.iter().any(|(n, _)| *n == name),
                    "hdl-out/{name} is not part of the default design: run `cargo run --release`"
                );
            }
        }
    }

    /// The variants beside the default design go into directories named after the
    /// parameters they set, with every other parameter the default design's.
    #[test]
    fn default_variants_have_directories_of_their_parameters() {
        let entries = default_entries();
        let dirs: Vec<_> = entries.iter().filter_map(|d| d.dir.clone()).collect();
        assert_eq!(dirs, ["raster_top-METHOD=1-LANES=4", "raster_top-METHOD=2", "raster_top-TEXTURE=1"]);
        let main = entries.iter().find(|d| d.unit.name == "raster_top" && d.dir.is_none()).expect("raster_top");
        let vector = entries.iter().find(|d| d.dir.as_deref() == Some("raster_top-METHOD=1-LANES=4")).expect("vector");
        for (k, v) in &main.params {
            let want = match k.as_str() {
                "METHOD" => 1,
                "LANES" => 4,
                _ => *v,
            };
            assert_eq!(vector.params[k], want, "{k}");
        }
        assert_eq!(file_name("raster_top", vector.dir.as_deref()), "raster_top-METHOD=1-LANES=4/raster_top.v");
        let textured = entries.iter().find(|d| d.dir.as_deref() == Some("raster_top-TEXTURE=1")).expect("textured");
        for (k, v) in &main.params {
            assert_eq!(textured.params[k], if k == "TEXTURE" { 1 } else { *v }, "{k}");
        }
    }

    /// One name per unit: `rtl/src/<name>.rs`, `model/src/<name>.rs` and
    /// `testbenches/tests/<name>.rs` exist for every unit in `UNITS`.
    #[test]
    fn units_have_one_name() {
        for unit in UNITS {
            for file in [
                format!("crates/rtl/src/{}.rs", unit.name),
                format!("crates/model/src/{}.rs", unit.name),
                format!("testbenches/tests/{}.rs", unit.name),
            ] {
                assert!(repo().join(&file).is_file(), "unit {}: {file} is missing", unit.name);
            }
        }
    }

    #[test]
    fn pnr_wrapper_registers_every_port() {
        let e = Unit::named("ept").expect("ept").emit(&[("P".to_owned(), 8)].into()).expect("P = 8");
        let w = pnr_wrapper(&e);
        for line in [
            "module ept_pnr(clk, sin, load, sout);",
            ".xl(chain_in[2:0])",
            ".xr(chain_in[5:3])",
            ".px(out_d[7:0])",
            "chain_in <= {chain_in[4:0], sin};",
            "chain_out <= load ? out_q : {chain_out[6:0], 1'b0};",
            "assign sout = chain_out[7];",
        ] {
            assert!(w.contains(line), "{line} missing from\n{w}");
        }
    }

    #[test]
    fn ports_are_read_off_the_unit() {
        let e = Unit::named("ept").expect("ept").emit(&[("P".to_owned(), 16)].into()).expect("P = 16");
        let names: Vec<_> = e.ports.iter().map(|p| (p.name.as_str(), p.dir, p.width)).collect();
        assert_eq!(names, [("xl", PortDir::In, 4), ("xr", PortDir::In, 4), ("px", PortDir::Out, 16)]);
        assert!(e.verilog.contains("\nmodule ept(xl,xr,px);"), "top module named after the unit");
    }
}

/// The widths of each size class's build (`rtl::n10`, and `n11`, `n12` with the feature
/// `classes-11-12`) against the formats
/// of 001/003 as the README gives them. (`rtl::custom`'s widths are whatever its formats
/// make them: its units are checked through raster_top's lockstep test.)
mod widths {
    macro_rules! check {
        ($build:ident) => {{
            use rtl::$build::widths::*;
            // Class 10: S11.4 vertices, positions in [-4096, 4096), edge deltas 17 bits,
            // D < 2^20; every width but the depth word's grows by a bit per class.
            let n = CLASS as usize - 10;
            assert_eq!(FORMATS, fx::Formats::for_n(CLASS), "{} is at its class's defaults", stringify!($build));
            assert_eq!(
                (SCREEN, DIM, ADDR, PIXEL, EDGE_D, EDGE_Q),
                (10 + n, 11 + n, 20 + 2 * n, 13 + n, 21 + n, 17 + n)
            );
            assert_eq!((Z_ACC, DZ, C_ACC, DC, DEPTH, CHANNEL, RGB), (36 + n, 40 + n, 32 + n, 36 + n, 16, 8, 24));
        }};
    }

    #[test]
    fn widths_follow_the_formats_of_each_size_class() {
        check!(n10);
        #[cfg(feature = "classes-11-12")]
        {
            check!(n11);
            check!(n12);
            assert_eq!(rtl::CLASSES, [10, 11, 12]);
        }
        #[cfg(not(feature = "classes-11-12"))]
        assert_eq!(rtl::CLASSES, [10]);
    }
}

/// `config::Widths`' link totals, which the sweep's area model counts, against the links
/// as declared (`Link::WIDTHS`), in every build.
mod link_bits {
    use rtl::link::Link;

    macro_rules! check {
        ($build:ident) => {{
            use rtl::$build::links::*;
            use rtl::$build::widths::WIDTHS;
            let bits = |w: &[usize]| w.iter().sum::<usize>();
            let build = stringify!($build);
            assert_eq!(WIDTHS.triangle_link(), bits(<TriangleSource as Link>::WIDTHS), "{build}: triangle");
            assert_eq!(WIDTHS.setup_link(), bits(<TriangleSetupSource as Link>::WIDTHS), "{build}: setup");
            assert_eq!(WIDTHS.span_cmd_link(), bits(<SpanCmdSource as Link>::WIDTHS), "{build}: span command");
            assert_eq!(WIDTHS.pixel_link(), bits(<PixelSource as Link>::WIDTHS), "{build}: pixel");
        }};
    }

    #[test]
    fn link_bits_of_the_width_table_equal_the_declared_links() {
        check!(n10);
        #[cfg(feature = "classes-11-12")]
        {
            check!(n11);
            check!(n12);
        }
        #[cfg(feature = "custom-formats")]
        check!(custom);
    }
}
