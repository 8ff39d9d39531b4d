//! The README's Dzhanibekov demo example, run and compared exactly: the
//! headless command of the "The Dzhanibekov demo" section (`cargo run
//! --release --example dzhanibekov -- ARGS`) must print the ```` ```text ````
//! block after "prints". The GIF and the chart go to a scratch directory
//! (their `docs/` paths are put back in the printed lines), so the test
//! leaves nothing behind. The other README examples are checked by
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

/// The headless command's arguments and the lines the README shows for it.
fn readme_example(readme: &str) -> (Vec<String>, Vec<String>) {
    let lines: Vec<&str> = readme.lines().collect();
    let at = lines
        .iter()
        .position(|l| l.starts_with(COMMAND_PREFIX))
        .expect("the README's headless demo command");
    let args = lines[at]
        .trim_start_matches("cargo run --release --example dzhanibekov -- ")
        .split_whitespace()
        .map(String::from)
        .collect();
    // The block closes, "prints" follows, then the ```text block.
    let rest = &lines[at + 1..];
    let open = rest
        .iter()
        .position(|l| *l == "```text")
        .expect("a ```text block after the command");
    assert!(
        rest[..open].iter().any(|l| l.trim() == "prints"),
        "\"prints\" between the command and its output"
    );
    let expected = rest[open + 1..]
        .iter()
        .take_while(|l| !l.starts_with("```"))
        .map(|l| (*l).to_owned())
        .collect();
    (args, expected)
}

#[test]
fn readme_demo_example_prints_what_the_readme_shows() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).expect("README.md");
    let (args, expected) = readme_example(&readme);
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("readme_demo");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scratch = format!("{}/", dir.display());
    let mut argv = vec![OsString::from("dzhanibekov")];
    argv.extend(
        args.iter()
            .map(|a| OsString::from(a.replacen("docs/", &scratch, 1))),
    );
    let mut out = Vec::new();
    let result = demo::run(argv, None, &mut out);
    std::fs::remove_dir_all(&dir).unwrap();
    result.expect("the demo runs");
    let printed = String::from_utf8(out)
        .expect("UTF-8 output")
        .replace(&scratch, "docs/");
    let actual: Vec<&str> = printed.lines().collect();
    let differing: Vec<String> = (0..expected.len().max(actual.len()))
        .filter(|&k| expected.get(k).map(String::as_str) != actual.get(k).copied())
        .map(|k| {
            format!(
                "  - {}\n  + {}",
                expected.get(k).map_or("(none)", String::as_str),
                actual.get(k).copied().unwrap_or("(none)")
            )
        })
        .collect();
    assert!(
        differing.is_empty(),
        "README.md's demo output differs from what `{COMMAND_PREFIX}{}` prints \
         (- README, + demo); update README.md with the + lines if the new output is right:\n{}",
        args[1..].join(" "),
        differing.join("\n")
    );
}
