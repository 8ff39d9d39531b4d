//! The README's Dzhanibekov demo commands, run and compared exactly: every
//! `cargo run --release --example dzhanibekov -- --headless ARGS` line of
//! README.md (the main command of "Two commands" and the GIF command of
//! "The Dzhanibekov demo") must print the ```` ```text ```` block after
//! "prints". The files they write go to a scratch directory (their
//! `target/` paths are put back in the printed lines), so the test leaves
//! nothing behind. CI runs the README's main command as written
//! (`.ci/run`): checked here too. The other README examples are checked by
//! `crates/cli/tests/readme.rs`.
//!
//! The demo's modules are compiled into this test (as in `tests/dzhanibekov.rs`).

#[allow(dead_code)]
#[path = "../examples/dzhanibekov/main.rs"]
mod demo;

use std::ffi::OsString;
use std::path::Path;

/// How the README runs the headless demo.
const COMMAND_PREFIX: &str = "cargo run --release --example dzhanibekov -- --headless ";

/// Where the README's commands write (ignored by git).
const OUTPUT_DIR: &str = "target/";

/// The section whose commands remake the committed images.
const IMAGES_SECTION: &str = "\n## The images in docs/\n";

/// One headless command of the README: its line, its arguments and the
/// lines the README shows for it.
struct Example {
    line: usize,
    args: Vec<String>,
    expected: Vec<String>,
}

/// Every headless demo command of `readme` with the ```text block after it.
fn readme_examples(readme: &str) -> Vec<Example> {
    // "The images in docs/" remakes the committed images: not run here.
    let readme = readme.split(IMAGES_SECTION).next().unwrap_or_default();
    let lines: Vec<&str> = readme.lines().collect();
    let mut found = Vec::new();
    for (at, line) in lines.iter().enumerate() {
        let Some(args) = line.strip_prefix("cargo run --release --example dzhanibekov -- ") else {
            continue;
        };
        if !line.starts_with(COMMAND_PREFIX) {
            continue;
        }
        // The block closes, "prints" follows, then the ```text block.
        let rest = &lines[at + 1..];
        let open = rest
            .iter()
            .position(|l| *l == "```text")
            .unwrap_or_else(|| panic!("README.md:{}: no ```text block after the command", at + 1));
        assert!(
            rest[..open].iter().any(|l| l.trim() == "prints"),
            "README.md:{}: \"prints\" between the command and its output",
            at + 1
        );
        found.push(Example {
            line: at + 1,
            args: args.split_whitespace().map(String::from).collect(),
            expected: rest[open + 1..]
                .iter()
                .take_while(|l| !l.starts_with("```"))
                .map(|l| (*l).to_owned())
                .collect(),
        });
    }
    found
}

/// The README's text.
fn readme() -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md"))
        .expect("README.md")
}

/// The differing lines of the README's `expected` and the demo's `printed`.
fn differing(expected: &[String], printed: &str) -> Vec<String> {
    let actual: Vec<&str> = printed.lines().collect();
    (0..expected.len().max(actual.len()))
        .filter(|&k| expected.get(k).map(String::as_str) != actual.get(k).copied())
        .map(|k| {
            format!(
                "  - {}\n  + {}",
                expected.get(k).map_or("(none)", String::as_str),
                actual.get(k).copied().unwrap_or("(none)")
            )
        })
        .collect()
}

#[test]
fn readme_demo_commands_print_what_the_readme_shows() {
    let readme = readme();
    let examples = readme_examples(&readme);
    // The main command and the GIF command of the demo's section.
    assert!(
        examples.len() >= 2,
        "{} headless demo commands",
        examples.len()
    );
    let mut failures = Vec::new();
    for (k, example) in examples.iter().enumerate() {
        let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("readme_demo_{k}"));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let scratch = format!("{}/", dir.display());
        let mut argv = vec![OsString::from("dzhanibekov")];
        argv.extend(example.args.iter().map(|a| {
            assert!(
                !a.starts_with("docs/"),
                "README.md:{}: writes the tracked {a}",
                example.line
            );
            OsString::from(a.replacen(OUTPUT_DIR, &scratch, 1))
        }));
        let mut out = Vec::new();
        let result = demo::run(argv, None, &mut out);
        std::fs::remove_dir_all(&dir).unwrap();
        result.expect("the demo runs");
        let printed = String::from_utf8(out)
            .expect("UTF-8 output")
            .replace(&scratch, OUTPUT_DIR);
        let lines = differing(&example.expected, &printed);
        if !lines.is_empty() {
            failures.push(format!(
                "README.md:{}: `{COMMAND_PREFIX}{}` prints (- README, + demo):\n{}",
                example.line,
                example.args[1..].join(" "),
                lines.join("\n")
            ));
        }
    }
    assert!(
        failures.is_empty(),
        "README.md's demo output differs from what the demo prints; update README.md \
         with the + lines if the new output is right:\n{}",
        failures.join("\n")
    );
}

/// The main command is the first command of "Two commands", and CI runs it
/// as written.
#[test]
fn ci_runs_the_readme_main_command() {
    let readme = readme();
    let section = readme
        .split("\n## Two commands\n")
        .nth(1)
        .expect("a \"Two commands\" section");
    let main = section
        .lines()
        .skip_while(|l| *l != "```sh")
        .find(|l| !l.starts_with('#') && *l != "```sh")
        .expect("a command in the section's first sh block");
    assert!(main.starts_with(COMMAND_PREFIX), "the main command: {main}");
    let ci = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(".ci/run"))
        .expect(".ci/run");
    assert!(
        ci.lines().any(|l| l == main),
        ".ci/run does not run the README's main command `{main}`"
    );
}
