//! `--plot`: well-formed SVG and PNG files of the right size.

use crate::support::{CASES, run_case, scratch_dir};

#[test]
fn svg_plot_is_well_formed() {
    for (k, case) in CASES.iter().enumerate() {
        let path = scratch_dir().join(format!("top{k}.svg"));
        let _ = std::fs::remove_file(&path);
        let run = run_case(case, &["--plot", path.to_str().unwrap()]);
        assert_eq!(run.code, Some(0), "{}", run.stderr);
        assert!(
            run.stdout.starts_with("i1: "),
            "the report is still written"
        );
        let svg = std::fs::read_to_string(&path).expect("svg written");
        assert!(
            svg.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""),
            "{}",
            &svg[..80]
        );
        assert!(svg.trim_end().ends_with("</svg>"));
        assert!(
            svg.matches("<polyline ").count() > 20,
            "curves, grid, circles"
        );
        assert!(svg.contains("width=\"1280\" height=\"640\""));
        // Every element opened is closed: self-closing or with its end tag.
        let opened = svg.matches('<').count();
        let closed = svg.matches("/>").count() + 2 * svg.matches("</").count();
        assert_eq!(opened, closed, "balanced tags");
        assert!(
            svg.contains("u = cos θ") && svg.contains("f(u)"),
            "axis labels"
        );
        assert!(svg.contains("I₁ = "), "title with the parameters");
        assert!(
            !svg.contains("NaN") && !svg.contains("inf"),
            "finite coordinates"
        );
    }
}

#[test]
fn png_plot_has_signature_and_size() {
    for (k, case) in [CASES[1], [1.0, 0.5, 1.0, 0.0, 0.0, 0.0, 5.0]]
        .iter()
        .enumerate()
    {
        let path = scratch_dir().join(format!("top{k}.png"));
        let _ = std::fs::remove_file(&path);
        let run = run_case(
            case,
            &["--plot", path.to_str().unwrap(), "--format", "json"],
        );
        assert_eq!(run.code, Some(0), "{}", run.stderr);
        let png = std::fs::read(&path).expect("png written");
        assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n", "signature");
        assert_eq!(&png[12..16], b"IHDR");
        let width = u32::from_be_bytes(png[16..20].try_into().unwrap());
        let height = u32::from_be_bytes(png[20..24].try_into().unwrap());
        assert_eq!((width, height), (1280, 640));
        assert!(png.len() > 20_000, "a drawn image, {} bytes", png.len());
        assert_eq!(&png[png.len() - 8..png.len() - 4], b"IEND");
    }
}
