//! The README's examples, run and compared exactly, so the docs cannot drift
//! from what the binary prints.
//!
//! Checked: every ```` ```console ```` block (each `$ ` line is run by bash,
//! standard output and error merged as a terminal shows them, and compared
//! line by line with the lines under it up to the next `$ ` line). An
//! example whose output shows `kreisel: error:` must exit non-zero, every
//! other one with 0 (`pipefail`, so `| head -3` does not hide kreisel's
//! status). Each block runs in its own scratch directory holding links to
//! the repository's top-level entries and an empty `target/`, so `--plot
//! target/top.svg` writes there and the test leaves nothing behind. (The
//! main command, the Dzhanibekov demo, is checked by `tests/readme_demo.rs`.)
//!
//! Also checked: every file a command of the README writes (`--output`,
//! `--plot`, `--gif`, `--csv`, `> FILE`) is one git ignores, so running the
//! README leaves `git status` clean; only the commands of "The images in
//! docs/" rewrite committed files, each an image the README shows; and the
//! links of the table of contents name headings.
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

/// The examples of `readme`: its console blocks' commands.
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
        if lang == "console" {
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
    // The README's commands write under target/ (cargo's, ignored by git).
    std::fs::create_dir(dir.join("target")).expect("scratch target/");
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
    assert!(console_commands >= 5, "{console_commands} console commands");
    assert_eq!(examples.len(), console_commands);

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
fn parser_finds_console_commands() {
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
        ]
    );
}

/// The section whose commands remake the committed images (and may write
/// committed files).
const IMAGES_SECTION: &str = "## The images in docs/";

/// Options whose value is a file the command writes.
const OUTPUT_OPTIONS: [&str; 4] = ["--output", "--plot", "--gif", "--csv"];

/// A command of the README's ```` ```sh ```` and ```` ```console ```` blocks.
#[derive(Debug, PartialEq)]
struct ShellCommand {
    /// 1-based line in README.md.
    line: usize,
    /// The command (continuation lines joined).
    text: String,
    /// Whether it is in [`IMAGES_SECTION`].
    remakes_images: bool,
}

/// Every command of `readme`: the `$ ` lines of console blocks and the lines
/// of sh blocks that are not comments.
fn shell_commands(readme: &str) -> Vec<ShellCommand> {
    let mut found = Vec::new();
    let (mut block, mut section_is_images) = (None::<String>, false);
    let mut pending: Option<ShellCommand> = None;
    for (k, line) in readme.lines().enumerate() {
        if let Some(lang) = line.strip_prefix("```") {
            block = match block {
                Some(_) => None,
                None => Some(lang.trim().to_owned()),
            };
            continue;
        }
        let Some(lang) = block.as_deref() else {
            if line.starts_with("## ") {
                section_is_images = line == IMAGES_SECTION;
            }
            continue;
        };
        let text = match (lang, &mut pending) {
            (_, Some(command)) => {
                command.text.push(' ');
                command.text.push_str(line.trim());
                None
            }
            ("console", None) => line.strip_prefix("$ "),
            ("sh", None) => Some(line).filter(|l| !l.trim().is_empty() && !l.starts_with('#')),
            _ => None,
        };
        if let Some(text) = text {
            pending = Some(ShellCommand {
                line: k + 1,
                text: text.to_owned(),
                remakes_images: section_is_images,
            });
        }
        if let Some(command) = pending.take_if(|c| !c.text.ends_with('\\')) {
            found.push(command);
        } else if let Some(command) = &mut pending {
            command.text.pop();
        }
    }
    found
}

/// The files `command` writes: the values of [`OUTPUT_OPTIONS`] and the
/// targets of `>` and `>>` (but `/dev/null`).
fn written_files(command: &str) -> Vec<String> {
    let words: Vec<&str> = command.split_whitespace().collect();
    let mut files = Vec::new();
    for (k, word) in words.iter().enumerate() {
        let next = || words.get(k + 1).map(|w| (*w).to_owned());
        let file = if OUTPUT_OPTIONS.contains(word) || matches!(*word, ">" | ">>") {
            next()
        } else if let Some((option, value)) = word.split_once('=') {
            OUTPUT_OPTIONS.contains(&option).then(|| value.to_owned())
        } else {
            word.strip_prefix(">>")
                .or_else(|| word.strip_prefix('>'))
                .filter(|f| !f.is_empty() && !f.starts_with('&'))
                .map(str::to_owned)
        };
        files.extend(
            file.map(|f| f.trim_matches(['"', '\'']).to_owned())
                .filter(|f| f != "/dev/null"),
        );
    }
    files
}

/// `git ARGS` in the repository; its exit code, or `None` without git or
/// outside a checkout.
fn git(args: &[&str]) -> Option<i32> {
    let output = Command::new("git")
        .args(args)
        .current_dir(repo_root())
        .output()
        .ok()?;
    output.status.code().filter(|&c| c != 128)
}

#[test]
fn readme_commands_write_only_files_git_ignores() {
    if git(&["rev-parse", "--is-inside-work-tree"]) != Some(0) {
        eprintln!("not a git checkout: nothing to compare with");
        return;
    }
    let readme = std::fs::read_to_string(repo_root().join("README.md")).expect("README.md");
    let commands = shell_commands(&readme);
    let mut problems = Vec::new();
    let mut written = 0;
    let mut remade = Vec::new();
    for command in &commands {
        for file in written_files(&command.text) {
            written += 1;
            let at = format!(
                "README.md:{}: `{}` writes {file}",
                command.line, command.text
            );
            if command.remakes_images {
                // `git ls-files --error-unmatch`: 0 when the file is committed.
                if !file.starts_with("docs/")
                    || git(&["ls-files", "--error-unmatch", "--", &file]) != Some(0)
                {
                    problems.push(format!("{at}, which is not a committed image in docs/"));
                }
                remade.push(file);
            } else if git(&["check-ignore", "-q", "--", &file]) != Some(0) {
                // `git check-ignore`: 0 for an ignored file, 1 for a committed
                // one or one `git status` would list.
                problems.push(format!(
                    "{at}, which git does not ignore (committed, or untracked and listed \
                     by `git status`): write it under target/"
                ));
            }
        }
    }
    // Guard against a parser that finds nothing: the main command's plot,
    // the console examples' files, the images.
    assert!(written >= 10, "{written} files written by README commands");
    let mut shown: Vec<String> = readme
        .split("](docs/")
        .skip(1)
        .filter_map(|rest| rest.split_once(')').map(|(f, _)| format!("docs/{f}")))
        .collect();
    shown.sort();
    shown.dedup();
    remade.sort();
    remade.dedup();
    assert_eq!(
        remade, shown,
        "the commands of \"{IMAGES_SECTION}\" must remake exactly the images the README shows"
    );
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

#[test]
fn shell_commands_and_written_files_are_found() {
    let readme = "```sh\n# a comment\nkreisel a --plot x.png \\\n  --output y.csv\n```\n\
                  ```console\n$ kreisel b > c.csv && cat c.csv\nout\n$ kreisel top --csv=d.csv > /dev/null 2>&1\n```\n\
                  ## The images in docs/\n```sh\nkreisel e --gif docs/e.gif >>log\n```\n";
    let found = shell_commands(readme);
    let summary: Vec<(usize, &str, bool)> = found
        .iter()
        .map(|c| (c.line, c.text.as_str(), c.remakes_images))
        .collect();
    assert_eq!(
        summary,
        vec![
            (3, "kreisel a --plot x.png  --output y.csv", false),
            (7, "kreisel b > c.csv && cat c.csv", false),
            (9, "kreisel top --csv=d.csv > /dev/null 2>&1", false),
            (13, "kreisel e --gif docs/e.gif >>log", true),
        ]
    );
    let files: Vec<Vec<String>> = found.iter().map(|c| written_files(&c.text)).collect();
    assert_eq!(
        files,
        vec![
            vec!["x.png".to_owned(), "y.csv".to_owned()],
            vec!["c.csv".to_owned()],
            vec!["d.csv".to_owned()],
            vec!["docs/e.gif".to_owned(), "log".to_owned()],
        ]
    );
}

/// GitHub's anchor of a heading: lower case, spaces to `-`, punctuation dropped.
fn anchor(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter(|c| c.is_alphanumeric() || matches!(c, ' ' | '-' | '_'))
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

#[test]
fn table_of_contents_links_every_section() {
    let readme = std::fs::read_to_string(repo_root().join("README.md")).expect("README.md");
    let mut in_code = false;
    let mut headings = Vec::new();
    for line in readme.lines() {
        in_code ^= line.starts_with("```");
        if !in_code && (line.starts_with("## ") || line.starts_with("### ")) {
            headings.push((
                line.starts_with("## "),
                anchor(line.trim_start_matches('#')),
            ));
        }
    }
    let contents = readme
        .lines()
        .skip_while(|l| !l.starts_with("Contents:"))
        .take_while(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join(" ");
    assert!(!contents.is_empty(), "no \"Contents:\" paragraph");
    let links: Vec<&str> = readme
        .split("](#")
        .skip(1)
        .filter_map(|rest| rest.split_once(')').map(|(a, _)| a))
        .collect();
    for link in &links {
        assert!(
            headings.iter().any(|(_, a)| a == link),
            "README.md links #{link}, which no heading has"
        );
    }
    for (top_level, a) in &headings {
        assert!(
            !top_level || contents.contains(&format!("](#{a})")),
            "the contents do not list the section #{a}"
        );
    }
    assert_eq!(anchor(" `kreisel` on your PATH"), "kreisel-on-your-path");
    assert_eq!(
        anchor(" Game engines: rapier, bevy, avian"),
        "game-engines-rapier-bevy-avian"
    );
}
