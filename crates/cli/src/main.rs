//! `kreisel`: the command-line tool of the kreisel rigid-body rotation
//! library (everything but this entry point is in the `kreisel_cli` library).

#![forbid(unsafe_code)]

fn main() -> std::process::ExitCode {
    kreisel_cli::main()
}
