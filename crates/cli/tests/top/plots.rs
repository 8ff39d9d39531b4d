//! `--plot`: well-formed SVG and PNG files of the right size.

use crate::support::{CASES, Case, run_case, scratch_dir};

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

/// The texts of an SVG's `<text>` elements.
fn svg_texts(svg: &str) -> Vec<String> {
    svg.split("<text ")
        .skip(1)
        .filter_map(|t| Some(t.split_once('>')?.1.split_once("</text>")?.0.to_owned()))
        .collect()
}

/// Issue 25: released from rest without spin (a = b = 0), f(u) =
/// (1 − u²)(α − βu) has the roots −1 (the axis swings through the bottom:
/// u₁), cos θ₀ (u₂) and +1, the cubic's third root (u₃): two roots were
/// both labelled u₂.
#[test]
fn roots_are_named_u1_u2_u3_when_one_is_a_pole() {
    let cases: [(Case, [&str; 3]); 3] = [
        // β > 0, the pole u = 1 is the third root.
        (
            [0.3, 0.1, 2.0, 0.5, 0.0, 0.0, 0.0],
            ["u₁ = -1", "u₂ = 0.877583", "u₃ = 1"],
        ),
        // β < 0 (centre of mass below the pivot): u = −1 is the third root.
        (
            [0.3, 0.1, -2.0, 0.5, 0.0, 0.0, 0.0],
            ["u₃ = -1", "u₁ = 0.877583", "u₂ = 1"],
        ),
        // An ordinary fast top: u₃ far off scale.
        (
            [0.3, 0.1, 2.0, 0.5, 0.0, 0.0, 60.0],
            ["u₁ = 0.869447", "u₂ = 0.877583", "u₃ = 29.1306 (off scale)"],
        ),
    ];
    for (k, (case, want)) in cases.iter().enumerate() {
        let path = scratch_dir().join(format!("roots{k}.svg"));
        let run = run_case(case, &["--plot", path.to_str().unwrap()]);
        assert_eq!(run.code, Some(0), "{}", run.stderr);
        let texts = svg_texts(&std::fs::read_to_string(&path).unwrap());
        let roots: Vec<&String> = texts
            .iter()
            .filter(|t| ["u₁ = ", "u₂ = ", "u₃ = "].iter().any(|n| t.starts_with(n)))
            .collect();
        assert_eq!(roots.len(), 3, "{roots:?}");
        for name in want {
            assert!(
                texts.iter().any(|t| t == name),
                "{case:?}: no {name:?} in {roots:?}"
            );
        }
    }
}
