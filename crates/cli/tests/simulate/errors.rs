//! Bad scenes and options: one `kreisel: error: SCENE:LINE: message` line
//! naming the key, exit status 1 (2 for usage errors), never a panic.

use crate::support::{body, kreisel, scratch, simulate, simulate_file, simulation};

/// Runs the scene and checks the one error line: `SCENE:LINE: ` and then
/// every one of `needles`.
fn check(name: &str, scene: &str, line: u32, needles: &[&str]) {
    let path = scratch(name, scene);
    let run = simulate_file(&path, &[]);
    let message = run.error_line(1);
    let prefix = format!("kreisel: error: {}:{line}: ", path.display());
    assert!(
        message.starts_with(&prefix),
        "{message}\nexpected prefix {prefix}"
    );
    for needle in needles {
        assert!(message.contains(needle), "{needle} not in {message}");
    }
}

const SIM: &str = "[simulation]\nduration = 1.0\ndt = 0.01\n";
const BODY: &str =
    "[[body]]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\nangular_velocity = [0.01, 1.0, 0.0]\n";

#[test]
fn simulation_table_errors() {
    check(
        "unknown_key.toml",
        &format!("{SIM}speed = 2\n{BODY}"),
        4,
        &["unknown field `speed`", "`simulation`"],
    );
    let unknown_in_body = format!("{SIM}{BODY}colour = \"red\"\n");
    check(
        "unknown_body_key.toml",
        &unknown_in_body,
        8,
        &["unknown field `colour`", "`body`"],
    );
    check(
        "missing_dt.toml",
        &format!("[simulation]\nduration = 1.0\n{BODY}"),
        1,
        &["missing field `dt`"],
    );
    check(
        "zero_dt.toml",
        &(simulation(1.0, 0.0, "") + BODY),
        3,
        &["`dt` must be positive", "got 0"],
    );
    check(
        "negative_dt.toml",
        &(simulation(1.0, -0.01, "") + BODY),
        3,
        &["`dt` must be positive"],
    );
    check(
        "negative_duration.toml",
        &(simulation(-1.0, 0.01, "") + BODY),
        2,
        &["`duration` must be positive"],
    );
    check(
        "nan_dt.toml",
        &format!("[simulation]\nduration = 1.0\ndt = nan\n{BODY}"),
        3,
        &["`dt`", "finite"],
    );
    check(
        "string_dt.toml",
        &format!("[simulation]\nduration = 1.0\ndt = \"fast\"\n{BODY}"),
        3,
        &["`simulation.dt`", "invalid type"],
    );
    check(
        "too_many_steps.toml",
        &(simulation(1e10, 1e-3, "") + BODY),
        3,
        &["more than the limit of 1000000000", "`dt`"],
    );
    check(
        "tiny_dt.toml",
        &(simulation(1.0, 1e-300, "") + BODY),
        3,
        &["limit"],
    );
    check(
        "bad_interval.toml",
        &(simulation(1.0, 0.01, "output_interval = 0.015") + BODY),
        4,
        &["`output_interval`", "whole multiple of `dt`"],
    );
    check(
        "unknown_method.toml",
        &(simulation(1.0, 0.01, "method = \"euler\"") + BODY),
        4,
        &[
            "`method`",
            "unknown method `euler`",
            "auto, exact, rk4",
            "splitting8",
        ],
    );
    check(
        "bad_gravity.toml",
        &(simulation(1.0, 0.01, "gravity = [0.0, -9.81]") + BODY),
        4,
        &["`simulation.gravity`", "length 2"],
    );
    check(
        "syntax.toml",
        "[simulation\nduration = 1\n",
        1,
        &["expected"],
    );
    check(
        "body_table.toml",
        &format!("{SIM}[body]\nmass = 1.0\n"),
        4,
        &["[[body]]"],
    );
}

#[test]
fn body_errors() {
    let with =
        |extra: &str| format!("{SIM}[[body]]\nangular_velocity = [0.0, 1.0, 0.0]\n{extra}\n");
    check(
        "zero_quat.toml",
        &with("mass = 1.0\ninertia = [1.0, 2.0, 3.0]\norientation = [0.0, 0.0, 0.0, 0.0]"),
        8,
        &["body `body1`", "`orientation`", "not zero"],
    );
    check(
        "triangle.toml",
        &with("mass = 1.0\ninertia = [1.0, 1.0, 3.0]"),
        7,
        &["`inertia`", "triangle inequality"],
    );
    check(
        "negative_moment.toml",
        &with("mass = 1.0\ninertia = [-1.0, 2.0, 3.0]"),
        7,
        &["`inertia`", "positive"],
    );
    check(
        "zero_mass.toml",
        &with("mass = 0.0\ninertia = [1.0, 2.0, 3.0]"),
        6,
        &["`mass` must be positive"],
    );
    check(
        "no_mass.toml",
        &with("inertia = [1.0, 2.0, 3.0]"),
        4,
        &["`mass`", "missing"],
    );
    check(
        "no_inertia.toml",
        &with("mass = 1.0"),
        4,
        &["use exactly one of `inertia`, `inertia_tensor` and `mesh`"],
    );
    check(
        "inertia_and_mesh.toml",
        &with("mass = 1.0\ninertia = [1.0, 2.0, 3.0]\nmesh = \"t.obj\"\ndensity = 1.0"),
        8,
        &["both `inertia` and `mesh`"],
    );
    check(
        "inertia_and_tensor.toml",
        &with(
            "mass = 1.0\ninertia = [1.0, 2.0, 3.0]\ninertia_tensor = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]",
        ),
        8,
        &["both `inertia` and `inertia_tensor`"],
    );
    check(
        "bad_tensor.toml",
        &with("mass = 1.0\ninertia_tensor = [[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]"),
        7,
        &["`inertia_tensor`"],
    );
    check(
        "missing_mesh.toml",
        &with("mesh = \"no_such_mesh.obj\"\ndensity = 2700.0"),
        6,
        &["`mesh`", "no_such_mesh.obj", "cannot read"],
    );
    check(
        "mesh_with_mass.toml",
        &with("mesh = \"t.obj\"\ndensity = 2700.0\nmass = 1.0"),
        8,
        &["`mass` cannot be given with `mesh`"],
    );
    check(
        "mesh_without_density.toml",
        &with("mesh = \"t.obj\""),
        6,
        &["`mesh` needs `density`"],
    );
    check(
        "density_without_mesh.toml",
        &with("mass = 1.0\ninertia = [1.0, 2.0, 3.0]\ndensity = 5.0"),
        8,
        &["`density` is only used with `mesh`"],
    );
    check(
        "both_attitudes.toml",
        &with(
            "mass = 1.0\ninertia = [1.0, 2.0, 3.0]\norientation = [1.0, 0.0, 0.0, 0.0]\neuler = { sequence = \"ZXZ\", angles = [0.1, 0.2, 0.3] }",
        ),
        9,
        &["both `orientation` and `euler`"],
    );
    check(
        "bad_sequence.toml",
        &with(
            "mass = 1.0\ninertia = [1.0, 2.0, 3.0]\neuler = { sequence = \"ZZX\", angles = [0.1, 0.2, 0.3] }",
        ),
        8,
        &["`euler.sequence`", "ZZX"],
    );
    check(
        "nan_omega.toml",
        &format!(
            "{SIM}[[body]]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\nangular_velocity = [0.0, nan, 0.0]\n"
        ),
        7,
        &["`angular_velocity` must be finite"],
    );
    check(
        "no_omega.toml",
        &format!("{SIM}[[body]]\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]\n"),
        4,
        &["missing field `angular_velocity`"],
    );
    check(
        "comma_name.toml",
        &with("name = \"a,b\"\nmass = 1.0\ninertia = [1.0, 2.0, 3.0]"),
        6,
        &["`name`", "commas"],
    );
    let twice = format!(
        "{SIM}{}{}",
        body([1.0, 1.0, 1.0], [0.0, 0.0, 1.0], "name = \"a\""),
        body([1.0, 1.0, 1.0], [0.0, 0.0, 1.0], "name = \"a\"")
    );
    check("same_name.toml", &twice, 13, &["`a` is used twice"]);
}

#[test]
fn whole_file_and_option_errors() {
    // No bodies: the file as a whole, no line.
    let path = scratch("no_bodies.toml", SIM);
    let run = simulate_file(&path, &[]);
    assert_eq!(
        run.error_line(1),
        format!(
            "kreisel: error: {}: the scene has no bodies: add a [[body]] table",
            path.display()
        )
    );
    let run = kreisel(&["simulate", "/no/such/scene.toml"]);
    assert!(
        run.error_line(1)
            .contains("cannot read scene file /no/such/scene.toml")
    );
    // --method is checked before the scene is read.
    let run = kreisel(&["simulate", "/no/such/scene.toml", "--method", "leapfrog"]);
    let line = run.error_line(1);
    assert!(
        line.starts_with(
            "kreisel: error: --method: unknown method `leapfrog` (known: auto, exact, rk4,"
        ),
        "{line}"
    );
    // The output may not overwrite the scene.
    let path = scratch("self_output.toml", format!("{SIM}{BODY}"));
    let run = simulate_file(&path, &["--output", path.to_str().unwrap()]);
    assert!(run.error_line(1).contains("refusing to overwrite"));
    assert!(
        std::fs::read_to_string(&path)
            .unwrap()
            .contains("[simulation]")
    );
    // Usage errors are clap's, status 2.
    let run = kreisel(&["simulate"]);
    assert_eq!(run.code, Some(2), "{}", run.stderr);
    let run = simulate("usage.toml", &format!("{SIM}{BODY}"), &["--frobnicate"]);
    assert_eq!(run.code, Some(2), "{}", run.stderr);
}
