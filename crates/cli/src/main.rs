//! `kreisel`: the command-line tool of the kreisel rigid-body rotation
//! library (everything but this entry point is in the `kreisel_cli` library).

#![forbid(unsafe_code)]

fn main() -> std::process::ExitCode {
    // Without the handlers a signal leaves a temporary file behind; the
    // run itself does not need them.
    let _ = kreisel_cli::output::atomic_file::remove_on_signals();
    kreisel_cli::main()
}
