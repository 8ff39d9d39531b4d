//! The README's examples, run and compared exactly, so the docs cannot drift
//! from what the binary prints.
//!
//! Checked: every ```` ```console ```` block (each `$ ` line is run by bash,
//! standard output and error merged as a terminal shows them, and compared
//! line by line with the lines under it up to the next `$ ` line), and the
//! main command: a `cargo run ... -p kreisel-cli -- ARGS` line in a ```` ```sh ````
//! block followed by "prints `LINE`" runs as `kreisel ARGS` and must print
//! exactly LINE. An example whose output shows `kreisel: error:` must exit
//! non-zero, every other one with 0 (`pipefail`, so `| head -3` does not hide
//! kreisel's status). Each block runs in its own scratch directory holding
//! links to the repository's top-level entries, so `--plot top.svg` writes
//! there and the test leaves nothing behind.
//!
//! Why not `trycmd`: the README's examples are shell pipelines
//! (`printf ... | kreisel convert`, `kreisel simulate ... | head -3`,
//! `| sed -n '1p;202p'`) and a here-string (`<<<`); trycmd runs one program
//! per `$` line with no shell, so it could not run them without rewriting
//! the README into less useful examples (and it has no way to say "this
//! example exits 1" without a `? failed` line in the README). It is also
//! heavier: a cold `cargo test --no-run` of an empty crate with only trycmd
//! 0.15 as dev-dependency compiled 59 crates, 42 s of CPU (4 min 44 s wall
//! on this loaded 2-core machine); this test needs only std. The `kreisel inertia`, `simulate` and `top`
//! tests check the numbers against references; this test only keeps the
//! README's copies of the output exact.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The binary under test.
const KREISEL: &str = env!("CARGO_BIN_EXE_kreisel");

/// How the README runs the main command (replaced by `kreisel `).
const MAIN_COMMAND_PREFIX: &str = "cargo run --release -p kreisel-cli -- ";

/// The repository root (the README's working directory).
fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// One command of the README and the output shown under it.
#[derive(Debug)]
struct Example {
    /// 1-based line of the command in README.md.
    line: usize,
    /// The shell command, `kreisel ...` (with pipes).
    command: String,
    /// The lines shown as its output.
    expected: Vec<String>,
    /// Examples with the same block number share a scratch directory.
    block: usize,
}

/// The examples of `readme`: console blocks and the main command.
fn examples(readme: &str) -> Vec<Example> {
    let lines: Vec<&str> = readme.lines().collect();
    let mut found = Vec::new();
    let mut i = 0;
    let mut block = 0;
    while i < lines.len() {
        let Some(lang) = lines[i].strip_prefix("```") else {
            i += 1;
            continue;
        };
        let lang = lang.trim().to_owned();
        let start = i + 1;
        let end = (start..lines.len())
            .find(|&j| lines[j].starts_with("```"))
            .unwrap_or_else(|| panic!("README.md:{}: unclosed code block", i + 1));
        block += 1;
        let body = &lines[start..end];
        match lang.as_str() {
            "console" => {
                for (k, text) in body.iter().enumerate() {
                    if let Some(command) = text.strip_prefix("$ ") {
                        found.push(Example {
                            line: start + k + 1,
                            command: command.to_owned(),
                            expected: Vec::new(),
                            block,
                        });
                    } else {
                        let last = found
                            .last_mut()
                            .filter(|e| e.block == block)
                            .unwrap_or_else(|| {
                                panic!(
                                    "README.md:{}: console block output before any `$ ` command",
                                    start + k + 1
                                )
                            });
                        last.expected.push((*text).to_owned());
                    }
                }
            }
            "sh" => {
                // "prints `...`" on the first line after the block.
                let printed = lines
                    .get(end + 1)
                    .and_then(|l| l.strip_prefix("prints `"))
                    .and_then(|l| l.split_once('`'))
                    .map(|(line, _)| line.to_owned());
                for (k, text) in body.iter().enumerate() {
                    if let Some(args) = text.strip_prefix(MAIN_COMMAND_PREFIX) {
                        let expected = printed.clone().unwrap_or_else(|| {
                            panic!(
                                "README.md:{}: main command without a \"prints `...`\" line",
                                start + k + 1
                            )
                        });
                        found.push(Example {
                            line: start + k + 1,
                            command: format!("kreisel {args}"),
                            expected: vec![expected],
                            block,
                        });
                    }
                }
            }
            _ => {}
        }
        i = end + 1;
    }
    found
}

/// A fresh directory linking to the repository's top-level entries.
fn scratch(block: usize) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("readme_block_{block}"));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("scratch directory");
    let root = repo_root().canonicalize().expect("repository root");
    for entry in std::fs::read_dir(&root).expect("read repository root") {
        let name = entry.expect("directory entry").file_name();
        if name == ".git" || name == "target" {
            continue;
        }
        std::os::unix::fs::symlink(root.join(&name), dir.join(&name)).expect("symlink");
    }
    dir
}

/// The line diff of `expected` (README) and `actual` (kreisel), by longest
/// common subsequence: `  ` same, `- ` README only, `+ ` kreisel only.
fn diff(expected: &[String], actual: &[&str]) -> String {
    let (n, m) = (expected.len(), actual.len());
    let mut lcs = vec![vec![0usize; m + 1]; n + 1];
    for i in (0..n).rev() {
        for j in (0..m).rev() {
            lcs[i][j] = if expected[i] == actual[j] {
                lcs[i + 1][j + 1] + 1
            } else {
                lcs[i + 1][j].max(lcs[i][j + 1])
            };
        }
    }
    let (mut i, mut j, mut out) = (0, 0, String::new());
    while i < n || j < m {
        if i < n && j < m && expected[i] == actual[j] {
            let _ = writeln!(out, "    {}", expected[i]);
            (i, j) = (i + 1, j + 1);
        } else if i < n && (j == m || lcs[i + 1][j] >= lcs[i][j + 1]) {
            let _ = writeln!(out, "  - {}", expected[i]);
            i += 1;
        } else {
            let _ = writeln!(out, "  + {}", actual[j]);
            j += 1;
        }
    }
    out
}

/// Runs one example in `dir`; a description of the mismatch, if any.
fn check(example: &Example, dir: &Path) -> Option<String> {
    let bin_dir = Path::new(KREISEL).parent().expect("binary directory");
    let path = std::env::join_paths(std::iter::once(bin_dir.to_path_buf()).chain(
        std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default()),
    ))
    .expect("PATH");
    // `exec 2>&1`: errors interleaved with the output, as a terminal shows them.
    let script = format!("exec 2>&1\nset -o pipefail\n{}", example.command);
    let output = Command::new("bash")
        .arg("-c")
        .arg(&script)
        .current_dir(dir)
        .env("PATH", path)
        .output()
        .expect("run bash");
    let text = String::from_utf8_lossy(&output.stdout);
    let actual: Vec<&str> = text.lines().collect();
    let wants_failure = example
        .expected
        .iter()
        .any(|l| l.starts_with("kreisel: error:"));
    let status_ok = output.status.success() != wants_failure;
    if actual == example.expected && status_ok {
        return None;
    }
    let mut report = format!("README.md:{}: `$ {}`\n", example.line, example.command);
    if actual != example.expected {
        report.push_str("  output differs (- README, + kreisel):\n");
        report.push_str(&diff(&example.expected, &actual));
    }
    if !status_ok {
        let _ = writeln!(
            report,
            "  exit status {} but the README shows {}",
            output.status,
            if wants_failure { "an error" } else { "success" }
        );
    }
    Some(report)
}

#[test]
fn readme_examples_print_what_the_readme_shows() {
    let readme = std::fs::read_to_string(repo_root().join("README.md")).expect("README.md");
    let examples = examples(&readme);
    // Guard against a README change that hides examples from this parser.
    let console_commands = readme
        .split("```console\n")
        .skip(1)
        .map(|block| {
            let body = block.split("```").next().unwrap_or_default();
            body.lines().filter(|l| l.starts_with("$ ")).count()
        })
        .sum::<usize>();
    let main_commands = examples
        .iter()
        .filter(|e| !readme.contains(&format!("$ {}", e.command)))
        .count();
    assert!(console_commands >= 5, "{console_commands} console commands");
    assert!(main_commands >= 1, "the main command was not found");
    assert_eq!(examples.len(), console_commands + main_commands);

    let mut failures = Vec::new();
    let mut current: Option<(usize, PathBuf)> = None;
    for example in &examples {
        if current.as_ref().is_none_or(|(b, _)| *b != example.block) {
            if let Some((_, dir)) = current.take() {
                std::fs::remove_dir_all(dir).expect("remove scratch directory");
            }
            current = Some((example.block, scratch(example.block)));
        }
        let (_, dir) = current.as_ref().expect("scratch directory");
        failures.extend(check(example, dir));
    }
    if let Some((_, dir)) = current {
        std::fs::remove_dir_all(dir).expect("remove scratch directory");
    }
    assert!(
        failures.is_empty(),
        "{} of {} README examples differ from what kreisel prints; update README.md \
         with the + lines if the new output is right:\n\n{}",
        failures.len(),
        examples.len(),
        failures.join("\n")
    );
}

#[test]
fn diff_marks_changed_lines() {
    let expected = ["a", "b", "c"].map(String::from);
    assert_eq!(
        diff(&expected, &["a", "x", "c", "d"]),
        "    a\n  - b\n  + x\n    c\n  + d\n"
    );
    assert_eq!(diff(&expected, &["a", "b", "c"]), "    a\n    b\n    c\n");
}

#[test]
fn parser_finds_console_commands_and_the_main_command() {
    let readme = "text\n```console\n$ kreisel a | head -1\nx\ny\n$ kreisel b\n```\n\
                  ```sh\n# comment\ncargo run --release -p kreisel-cli -- c <<< \"1\"\n```\n\
                  prints `z`.\n```text\n$ not run\n```\n";
    let found = examples(readme);
    let summary: Vec<(usize, &str, Vec<String>)> = found
        .iter()
        .map(|e| (e.line, e.command.as_str(), e.expected.clone()))
        .collect();
    assert_eq!(
        summary,
        vec![
            (3, "kreisel a | head -1", vec!["x".into(), "y".into()]),
            (6, "kreisel b", vec![]),
            (10, "kreisel c <<< \"1\"", vec!["z".into()]),
        ]
    );
}
