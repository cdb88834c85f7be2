//! The lockstep scene on the host: prints `name hash` for every scalar, the lines the bare-metal
//! `lockstep` program must print bit for bit (`.ci/embedded.sh` compares them). Contacts and
//! escapes go to stderr.
//!
//! Run: `cargo run --release --example lockstep` (debug builds must print the same).

#[path = "../embedded/src/lockstep.rs"]
mod lockstep;

fn main() {
    lockstep::run_all(|name, o| {
        println!("{name} {:016x}", o.hash);
        eprintln!(
            "{name}: {} steps, {} contacts, {} escapes",
            lockstep::STEPS,
            o.contacts,
            o.escapes
        );
    });
}
