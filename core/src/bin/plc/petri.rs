//! `plc petri …`: analyse a Petri net, print its generated ST, convert to and from PNML.

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::Subcommand;
use plc_core::petri::{self, PetriPou};
use plc_core::pnml;
use plc_core::project::Project;

/// The `petri` subcommands.
#[derive(Subcommand)]
pub enum PetriCommand {
    /// Analyse the net (guards ignored): bounds, deadlocks, liveness, reversibility,
    /// invariants, state-machine components.
    Analyze {
        /// A project file with a Petri net POU, or a PNML file.
        net: PathBuf,
        /// The Petri net POU (default: the first one).
        #[arg(long)]
        pou: Option<String>,
        /// How many markings to explore at most.
        #[arg(long, default_value_t = petri::DEFAULT_BUDGET)]
        budget: usize,
        /// Print one JSON object.
        #[arg(long)]
        json: bool,
    },
    /// Print the ST program generated from the net by the CASE OF method.
    Codegen {
        /// A project file with a Petri net POU, or a PNML file.
        net: PathBuf,
        /// The Petri net POU (default: the first one).
        #[arg(long)]
        pou: Option<String>,
        /// Print the place map (place → step variable and value) as JSON instead.
        #[arg(long = "place-map")]
        place_map: bool,
    },
    /// Convert a PNML file into a project file (printed to standard output).
    Import {
        /// The PNML file.
        file: PathBuf,
    },
    /// Print a Petri net POU of a project as PNML.
    Export {
        /// The project file (or a PNML file).
        project: PathBuf,
        /// The Petri net POU (default: the first one).
        #[arg(long)]
        pou: Option<String>,
    },
}

fn load(path: &Path) -> Result<Project, String> {
    let bytes =
        std::fs::read(path).map_err(|e| format!("plc: cannot read {}: {e}", path.display()))?;
    let text = String::from_utf8_lossy(&bytes);
    if pnml::is_pnml(&text) {
        return plc_core::open::open_text("net", &text)
            .map(|opened| opened.project)
            .map_err(|e| format!("plc: {}: {e}", path.display()));
    }
    Project::from_file(&text).map_err(|e| format!("plc: {}: {e}", path.display()))
}

/// The Petri net POU `pou` (or the first one) of the project or PNML file at `path`.
fn load_pou(path: &Path, pou: Option<&str>) -> Result<PetriPou, String> {
    let project = load(path)?;
    let names: Vec<String> = project.petri.iter().map(|p| p.name.clone()).collect();
    let found = match pou {
        Some(name) => project.petri.into_iter().find(|p| p.name.eq_ignore_ascii_case(name)),
        None => project.petri.into_iter().next(),
    };
    found.ok_or_else(|| match pou {
        Some(name) => format!(
            "plc: no Petri net POU `{name}` in {} (Petri net POUs: {})",
            path.display(),
            names.join(", ")
        ),
        None => format!("plc: {} holds no Petri net POU", path.display()),
    })
}

fn fail(message: String) -> ExitCode {
    eprintln!("{message}");
    ExitCode::from(2)
}

/// Prints diagnostics as `FILE: error[CODE]: POU P, place X (…): message`, on standard
/// error when standard output carries a result (generated code).
fn print_diagnostics(path: &Path, pou: &str, diags: &[petri::PetriDiagnostic], stderr: bool) {
    for d in diags {
        let severity = if d.is_error() { "error" } else { "warning" };
        let at = petri::describe(pou, &d.element, d.at.as_ref());
        let line = format!("{}: {severity}[{}]: {at}: {}", path.display(), d.code, d.message);
        if stderr {
            eprintln!("{line}");
        } else {
            println!("{line}");
        }
    }
}

/// Runs a `petri` subcommand.
pub fn run(command: PetriCommand) -> ExitCode {
    match command {
        PetriCommand::Analyze { net, pou, budget, json } => {
            analyze(&net, pou.as_deref(), budget, json)
        }
        PetriCommand::Codegen { net, pou, place_map } => codegen(&net, pou.as_deref(), place_map),
        PetriCommand::Import { file } => match load(&file) {
            Ok(p) => {
                println!("{}", p.to_file());
                ExitCode::SUCCESS
            }
            Err(e) => fail(e),
        },
        PetriCommand::Export { project, pou } => match load_pou(&project, pou.as_deref()) {
            Ok(p) => {
                print!("{}", pnml::export(&p));
                ExitCode::SUCCESS
            }
            Err(e) => fail(e),
        },
    }
}

fn analyze(path: &Path, pou: Option<&str>, budget: usize, json: bool) -> ExitCode {
    let pou = match load_pou(path, pou) {
        Ok(p) => p,
        Err(e) => return fail(e),
    };
    let net = match petri::build(&pou.net) {
        Ok(n) => n,
        Err(diags) => {
            print_diagnostics(path, &pou.name, &diags, false);
            return ExitCode::FAILURE;
        }
    };
    let analysis = petri::analyze(&net, budget);
    if json {
        eprintln!("plc: guards are ignored: the analysis is an over-approximation of the program");
        println!("{}", analysis.to_json(&net));
    } else {
        print!("{}", petri::text_report(&pou.net, &net, &analysis));
    }
    ExitCode::SUCCESS
}

fn codegen(path: &Path, pou: Option<&str>, place_map: bool) -> ExitCode {
    let pou = match load_pou(path, pou) {
        Ok(p) => p,
        Err(e) => return fail(e),
    };
    match petri::compile(&pou) {
        Ok(compiled) => {
            print_diagnostics(path, &pou.name, &compiled.warnings, true);
            if place_map {
                println!(
                    "{}",
                    serde_json::to_string_pretty(&compiled.generated.place_map).unwrap_or_default()
                );
            } else {
                print!("{}", compiled.generated.st);
            }
            ExitCode::SUCCESS
        }
        Err(diags) => {
            print_diagnostics(path, &pou.name, &diags, false);
            ExitCode::FAILURE
        }
    }
}
