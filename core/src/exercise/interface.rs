//! The declarations of an exercise's interface, for a POU the student starts from: each
//! input in `VAR_INPUT`, each output in `VAR_OUTPUT`, with its meaning as a comment.

use super::format::{Direction, InterfaceVar};

/// `VAR_INPUT … END_VAR` and `VAR_OUTPUT … END_VAR` declaring `interface` (a section with
/// no variable is left out), each variable with its meaning as a comment:
///
/// ```text
/// VAR_INPUT
///     Start : BOOL; (* start button (NO) *)
/// END_VAR
/// ```
pub fn interface_declarations(interface: &[InterfaceVar]) -> String {
    let mut text = String::new();
    for (direction, keyword) in [(Direction::Input, "VAR_INPUT"), (Direction::Output, "VAR_OUTPUT")]
    {
        let vars: Vec<&InterfaceVar> =
            interface.iter().filter(|v| v.direction == direction).collect();
        if vars.is_empty() {
            continue;
        }
        text.push_str(keyword);
        text.push('\n');
        for v in vars {
            // A comment cannot hold its own end.
            let meaning = v.meaning.trim().replace("*)", "* )");
            if meaning.is_empty() {
                text.push_str(&format!("    {} : {};\n", v.name, v.ty));
            } else {
                text.push_str(&format!("    {} : {}; (* {meaning} *)\n", v.name, v.ty));
            }
        }
        text.push_str("END_VAR\n");
    }
    text
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;
    use crate::ladder::LadderPouKind;
    use crate::project::Project;

    fn var(name: &str, ty: &str, direction: Direction, meaning: &str) -> InterfaceVar {
        InterfaceVar { name: name.into(), ty: ty.into(), direction, meaning: meaning.into() }
    }

    #[test]
    fn the_interface_is_declared_with_its_meanings() {
        let interface = [
            var("Motor", "BOOL", Direction::Output, "motor contactor"),
            var("Start", "BOOL", Direction::Input, "start button (NO)"),
            var("Stop", "BOOL", Direction::Input, "stop *) button"),
            var("Speed", "INT", Direction::Input, ""),
        ];
        assert_eq!(
            interface_declarations(&interface),
            "VAR_INPUT\n    Start : BOOL; (* start button (NO) *)\n    Stop : BOOL; (* stop * ) button *)\n    Speed : INT;\nEND_VAR\nVAR_OUTPUT\n    Motor : BOOL; (* motor contactor *)\nEND_VAR\n"
        );
        assert_eq!(
            interface_declarations(&interface[..1]),
            "VAR_OUTPUT\n    Motor : BOOL; (* motor contactor *)\nEND_VAR\n"
        );
        assert_eq!(interface_declarations(&[]), "");
    }

    #[test]
    fn a_ladder_pou_declared_so_builds() {
        let interface = [
            var("Start", "BOOL", Direction::Input, "start button"),
            var("Motor", "BOOL", Direction::Output, "motor"),
        ];
        let mut p = Project::new("p");
        let decls = format!("{}VAR\nEND_VAR\n", interface_declarations(&interface));
        p.add_ladder_pou_with("Latch1", LadderPouKind::Program, &decls).unwrap();
        p.settings.program = Some("Latch1".into());
        let build = crate::build::build_project(&p);
        assert!(!build.has_errors(), "{:?}", build.diagnostics);
        let sim = build.simulator_with_plant(Some("Latch1"), None).unwrap();
        assert!(sim.read("Start").is_ok() && sim.read("Motor").is_ok());
    }
}
