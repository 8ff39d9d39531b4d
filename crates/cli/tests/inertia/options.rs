//! Units, scale, density, total mass, model: what each option does, that
//! the output states it, and which combinations are usage errors.

use crate::support::{inertia, max_abs, num, rel, rows, vec3, workspace};

/// The T-handle demo mesh (coordinates in metres).
fn t_handle() -> std::path::PathBuf {
    workspace("assets/t_handle.obj")
}

#[test]
fn units_mm_scale_mass_by_1e_9_and_inertia_by_1e_15() {
    let metres = inertia(&t_handle(), &["--format", "json"]).json();
    let mm = inertia(&t_handle(), &["--units", "mm", "--format", "json"]).json();
    assert_eq!((&mm["units"], num(&mm["scale"])), (&"mm".into(), 0.001));
    assert!(rel(num(&mm["mass"]) / num(&metres["mass"]), 1e-9) <= 1e-13);
    assert!(rel(num(&mm["volume"]) / num(&metres["volume"]), 1e-9) <= 1e-13);
    assert!(rel(num(&mm["area"]) / num(&metres["area"]), 1e-6) <= 1e-13);
    let (i_mm, i_m) = (rows(&mm["inertia"]), rows(&metres["inertia"]));
    let error = max_abs(i_mm * 1e15 - i_m) / max_abs(i_m);
    assert!(error <= 1e-13, "{error:e}");
    let c_error = (vec3(&mm["center_of_mass"]) * 1e3 - vec3(&metres["center_of_mass"]))
        .abs()
        .max_element();
    assert!(c_error <= 1e-17, "{c_error:e}");
    // The text report states the assumption.
    let text = inertia(&t_handle(), &["--units", "mm"]).stdout;
    assert!(text.contains("mm (scale 0.001)"), "{text}");
}

#[test]
fn units_and_scale_agree() {
    for (unit, scale) in [
        ("mm", "0.001"),
        ("cm", "0.01"),
        ("m", "1"),
        ("in", "0.0254"),
    ] {
        let by_unit = inertia(&t_handle(), &["--units", unit, "--format", "json"]).json();
        let by_scale = inertia(&t_handle(), &["--scale", scale, "--format", "json"]).json();
        assert_eq!(by_unit["units"], unit);
        assert_eq!(by_scale["units"], "custom");
        for key in [
            "mass",
            "center_of_mass",
            "inertia",
            "principal_moments",
            "scale",
        ] {
            assert_eq!(by_unit[key], by_scale[key], "{unit}: {key}");
        }
    }
    let text = inertia(&t_handle(), &["--scale", "2"]).stdout;
    assert!(text.contains("1 unit = 2 m (scale 2)"), "{text}");
}

#[test]
fn defaults_are_stated() {
    let run = inertia(&t_handle(), &[]);
    assert_eq!(run.code, Some(0), "{}", run.stderr);
    assert!(run.stderr.is_empty(), "{}", run.stderr);
    for words in [
        "assets/t_handle.obj",
        "m (scale 1)",
        "1000 kg/m^3 (default: water)",
        "solid",
        "about the centre of mass, mesh axes",
        "body 't_handle'",
        "principal moments",
        "principal orientation",
    ] {
        assert!(run.stdout.contains(words), "{words:?} in\n{}", run.stdout);
    }
    let json = inertia(&t_handle(), &["--format", "json"]).json();
    assert_eq!(num(&json["density"]), 1000.0);
    assert_eq!(json["density_source"], "default (water)");
    assert_eq!(json["frame"], "center of mass, mesh axes");
    assert_eq!((&json["units"], num(&json["scale"])), (&"m".into(), 1.0));
    assert_eq!(json["model"], "solid");
    assert!(json.get("thickness").is_none());
    assert!(
        json["file"]
            .as_str()
            .is_some_and(|f| f.ends_with("t_handle.obj"))
    );
    // Density is linear: 1000 × the density-1 mass.
    let one = inertia(&t_handle(), &["--density", "1", "--format", "json"]).json();
    assert!(rel(num(&json["mass"]), 1000.0 * num(&one["mass"])) <= 1e-15);
}

#[test]
fn mass_sets_the_total_mass() {
    let json = inertia(&t_handle(), &["--mass", "2", "--format", "json"]).json();
    assert!(rel(num(&json["mass"]), 2.0) <= 1e-14, "{}", json["mass"]);
    assert!(rel(num(&json["density"]), 2.0 / num(&json["volume"])) <= 1e-15);
    assert_eq!(json["density_source"], "from total mass");
    let text = inertia(&t_handle(), &["--mass", "2"]).stdout;
    assert!(text.contains("(from total mass 2 kg)"), "{text}");
}

#[test]
fn shell_thickness_default_is_stated() {
    let json = inertia(&t_handle(), &["--shell", "--format", "json"]).json();
    assert_eq!(
        (&json["model"], num(&json["thickness"])),
        (&"shell".into(), 0.001)
    );
    let expected = 1000.0 * 0.001 * num(&json["area"]);
    assert!(rel(num(&json["mass"]), expected) <= 1e-14);
    let text = inertia(&t_handle(), &["--shell"]).stdout;
    assert!(text.contains("shell of thickness 0.001 m"), "{text}");
    let urdf = inertia(
        &t_handle(),
        &["--shell", "--thickness", "0.002", "--format", "urdf"],
    )
    .stdout;
    assert!(urdf.contains("shell of thickness 0.002 m"), "{urdf}");
    let hull = inertia(&t_handle(), &["--hull", "--format", "json"]).json();
    assert_eq!(hull["model"], "convex hull");
    // The hull fills in the T's corners.
    let solid = inertia(&t_handle(), &["--format", "json"]).json();
    assert!(num(&hull["volume"]) > num(&solid["volume"]));
}

#[test]
fn conflicting_or_incomplete_options_are_usage_errors() {
    for args in [
        &["--density", "1", "--mass", "2"][..],
        &["--scale", "2", "--units", "cm"],
        &["--thickness", "0.1"],
        &["--shell", "--hull"],
        &["--format", "xml"],
        &["--units", "ft"],
    ] {
        let run = inertia(&t_handle(), args);
        assert_eq!(run.code, Some(2), "{args:?}: {}", run.stderr);
        assert!(
            run.stdout.is_empty() && !run.stderr.contains("panicked"),
            "{args:?}"
        );
    }
}
