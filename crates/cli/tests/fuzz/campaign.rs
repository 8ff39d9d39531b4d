//! The fuzz campaign: N mutated inputs per parser through the binary,
//! counting panics, hangs past 10 s and exit-0 runs with non-finite output.
//!
//! Ignored in CI; run it in release (see `main.rs`). Settings from the
//! environment: `KREISEL_FUZZ_CASES` (default 1000 per parser),
//! `KREISEL_FUZZ_JOBS` (parallel runs, default 2), `KREISEL_FUZZ_FINDINGS`
//! (where the inputs of defects are saved, up to 20 per parser and kind;
//! default under the target directory), `KREISEL_FUZZ_ONLY` (one target
//! name, e.g. `obj`). Case k of a parser is the same input on every run.

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Instant;

use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

use crate::mutate::mutated;
use crate::through_cli::{Defect, Parser, prepare, run, scratch};

/// Findings saved per parser and kind of defect.
const SAVED_PER_KIND: usize = 20;

fn setting(name: &str, default: usize) -> usize {
    std::env::var(name)
        .ok()
        .map(|v| {
            v.parse()
                .unwrap_or_else(|_| panic!("{name}={v}: not a count"))
        })
        .unwrap_or(default)
}

/// Input `k` of `target`: a proptest runner seeded by (target, k).
fn input(strategy: &impl Strategy<Value = Vec<u8>>, target: &str, k: usize) -> Vec<u8> {
    let mut seed = [0u8; 32];
    seed[..8].copy_from_slice(&(k as u64).to_le_bytes());
    for (slot, b) in seed[8..].iter_mut().zip(target.bytes()) {
        *slot = b;
    }
    let rng = TestRng::from_seed(RngAlgorithm::ChaCha, &seed);
    let mut runner = TestRunner::new_with_rng(Config::default(), rng);
    strategy
        .new_tree(&mut runner)
        .expect("generate an input")
        .current()
}

#[test]
#[ignore = "minutes: the fuzz campaign, run by hand in release"]
fn campaign() {
    let cases = setting("KREISEL_FUZZ_CASES", 1000);
    let jobs = setting("KREISEL_FUZZ_JOBS", 2).max(1);
    let findings = std::env::var_os("KREISEL_FUZZ_FINDINGS")
        .map_or_else(|| scratch("findings"), PathBuf::from);
    let only = std::env::var("KREISEL_FUZZ_ONLY").ok();
    std::fs::create_dir_all(&findings).expect("findings directory");
    let mut summary = Vec::new();
    for parser in Parser::ALL {
        let target = parser.target();
        if only.as_deref().is_some_and(|o| o != target) {
            continue;
        }
        let started = Instant::now();
        let next = AtomicUsize::new(0);
        let counts = Mutex::new(BTreeMap::<&'static str, usize>::new());
        let hang_output = Mutex::new(Vec::new());
        std::thread::scope(|scope| {
            for job in 0..jobs {
                let (next, counts, hang_output, findings) =
                    (&next, &counts, &hang_output, &findings);
                scope.spawn(move || {
                    let strategy = mutated(target);
                    let dir = scratch(&format!("campaign_{target}_{job}"));
                    loop {
                        let k = next.fetch_add(1, Ordering::Relaxed);
                        if k >= cases {
                            break;
                        }
                        let bytes = input(&strategy, target, k);
                        let case = prepare(parser, &bytes, k, &dir);
                        let outcome = run(parser, &case);
                        let status = match outcome.code {
                            Some(0) => "exit 0",
                            Some(1) => "exit 1",
                            Some(2) => "exit 2",
                            _ => "other",
                        };
                        *counts.lock().unwrap().entry(status).or_default() += 1;
                        let Some(defect) = outcome.defect else {
                            continue;
                        };
                        if let Defect::Hang { stdout_bytes } = defect {
                            hang_output.lock().unwrap().push(stdout_bytes);
                        }
                        let seen = {
                            let mut counts = counts.lock().unwrap();
                            let n = counts.entry(defect.kind()).or_default();
                            *n += 1;
                            *n
                        };
                        if seen <= SAVED_PER_KIND {
                            let stem = format!("{target}-{}-{k}", defect.kind());
                            let file = findings.join(format!("{stem}.{}", parser.extension()));
                            std::fs::write(&file, &bytes).expect("save finding");
                            let note = format!(
                                "kreisel {}\n(input file: {}; for convert the first 3 bytes pick \
                                 the representations and the rest is standard input)\n{defect:?}\n",
                                case.args.join(" "),
                                file.display()
                            );
                            std::fs::write(findings.join(format!("{stem}.txt")), note)
                                .expect("save note");
                        }
                    }
                    let _ = std::fs::remove_dir_all(&dir);
                });
            }
        });
        let counts = counts.into_inner().unwrap();
        let count = |kind| counts.get(kind).copied().unwrap_or(0);
        let hangs = hang_output.into_inner().unwrap();
        let line = format!(
            "{target:>13}: {cases} cases in {:.0} s: {} panics, {} hangs > 10 s ({} of them \
             still writing output), {} exit 0 with non-finite output; exit status 0 / 1 / 2: \
             {} / {} / {}",
            started.elapsed().as_secs_f64(),
            count("panic"),
            count("hang"),
            hangs.iter().filter(|&&b| b > 0).count(),
            count("nonfinite"),
            count("exit 0"),
            count("exit 1"),
            count("exit 2"),
        );
        println!("{line}");
        summary.push(line);
    }
    println!(
        "\nfindings in {}\n{}",
        findings.display(),
        summary.join("\n")
    );
}
