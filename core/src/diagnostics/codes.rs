//! The table of problem codes. One row per code: the enum variant, the stable code that
//! students search for, and a one-line title. `explain.rs` holds each code's explanation
//! with a wrong and a right example; `docs/problems.md` and the site's `problems.html` are
//! generated from both (`plc explain --markdown`, `--html`), and a test fails when a code
//! has no explanation or a page is not current.
//!
//! Ranges: E0001–E0099 lexical and syntax errors (the parser), E0100–E0299 name and type
//! errors (the checker), E0300–E0349 problems with how a program is run, E0400–E0449 ladder
//! diagrams (W0005–W0009 are ladder warnings), E0500–E0549 Petri nets (W0010–W0019 are Petri
//! net warnings), E0550–E0579 textual SFC (W0020–W0029 are SFC warnings), E0580–E0599
//! Instruction List, E0620–E0639 configurations and tasks, W0001–W0004 and W0030– other
//! warnings.

use serde::Serialize;

macro_rules! problem_codes {
    ($( $variant:ident = $code:literal : $title:literal, )*) => {
        /// A stable problem code. `Display` prints the code (`E0042`).
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        #[non_exhaustive]
        pub enum Code {
            $(
                #[doc = $title]
                $variant,
            )*
        }

        impl Code {
            /// The code as students see it, e.g. `E0042`.
            pub fn as_str(self) -> &'static str {
                match self { $( Code::$variant => $code, )* }
            }

            /// A one-line explanation of the code.
            pub fn title(self) -> &'static str {
                match self { $( Code::$variant => $title, )* }
            }

            /// Every code, in table order.
            pub fn all() -> &'static [Code] {
                &[ $( Code::$variant, )* ]
            }
        }
    };
}

problem_codes! {
    // ---- lexical and syntax errors (parser): E0001–E0099 ----
    UnexpectedCharacter = "E0001": "a character that cannot start any token",
    UnterminatedComment = "E0002": "a comment that is never closed",
    UnterminatedString = "E0003": "a string literal that is never closed",
    InvalidNumber = "E0004": "a malformed numeric literal",
    InvalidTimeLiteral = "E0005": "a malformed duration literal (T#…)",
    UnexpectedToken = "E0006": "the parser expected something else here",
    MissingEnd = "E0007": "a block is not closed by its END_ keyword",
    InvalidEscape = "E0008": "an unknown `$` escape in a string literal",
    InvalidDirectAddress = "E0009": "a malformed directly represented variable (%IX…)",
    InvalidDateLiteral = "E0010": "a malformed date or time-of-day literal",
    InvalidIdentifier = "E0011": "an identifier with a trailing or doubled underscore",
    IntegerLiteralTooLarge = "E0012": "an integer literal too large for any integer type",
    InvalidTypedLiteral = "E0013": "a type prefix that does not fit its literal",
    TooComplex = "E0014": "an expression, statement, type or file nested or chained beyond the trainer's limits",

    // ---- names and declarations (checker): E0100–E0149 ----
    UndeclaredName = "E0100": "a name that is not declared",
    DuplicateDeclaration = "E0101": "a name declared twice in the same scope",
    UnknownType = "E0102": "a type name that is not declared",
    NotAVariable = "E0103": "a name used as a variable that is something else",
    NoSuchMember = "E0104": "a struct or function block has no member of that name",
    NoProgram = "E0105": "the source holds no PROGRAM to run",
    UnknownProgram = "E0106": "the PROGRAM asked for is not in the source",
    RecursiveCall = "E0107": "a POU calls itself, directly or indirectly",
    RecursiveType = "E0108": "a type contains itself",
    ExternalWithoutGlobal = "E0109": "VAR_EXTERNAL without a matching VAR_GLOBAL",
    InvalidLocation = "E0110": "an AT location that does not fit the variable's type",
    DuplicateEnumerator = "E0111": "an enumerator declared twice in one type",
    SectionNotAllowed = "E0112": "a VAR section that this kind of POU cannot have",

    // ---- types and expressions (checker): E0150–E0199 ----
    TypeMismatch = "E0150": "a value of one type where another is needed",
    NotAssignable = "E0151": "an assignment to something that cannot be written",
    AssignToConstant = "E0152": "an assignment to a CONSTANT or a system variable",
    OperatorTypeMismatch = "E0153": "an operator applied to types it does not accept",
    ConditionNotBool = "E0154": "a condition that is not BOOL",
    NotAnArray = "E0155": "an index applied to something that is not an array",
    WrongIndexCount = "E0156": "an array indexed with the wrong number of subscripts",
    NotAStruct = "E0157": "a `.member` applied to something without members",
    BitOutOfRange = "E0158": "a bit number beyond the width of the value",
    NotConstant = "E0159": "a value that must be known before the program runs",
    ConstantOutOfRange = "E0160": "a constant that does not fit its type",
    ConstantIndexOutOfRange = "E0161": "a constant array index outside the declared bounds",
    DivisionByZeroConstant = "E0162": "a division by a constant zero",
    ZeroForStep = "E0163": "a FOR loop with a constant step of zero",
    ForVariableNotInteger = "E0164": "a FOR control variable that is not an integer variable",
    CaseLabelType = "E0165": "a CASE label of a type that does not match the selector",
    DuplicateCaseLabel = "E0166": "a CASE label that overlaps an earlier one",
    InvalidRange = "E0167": "a range whose lower limit is above its upper limit",
    ExitOutsideLoop = "E0168": "EXIT or CONTINUE outside a loop",
    SubrangeViolation = "E0169": "a constant outside the subrange of its variable",
    InvalidArraySize = "E0170": "an array or string too large, or with bad bounds",
    TooManyInitializers = "E0171": "more initial values than array elements",
    NotAReference = "E0180": "`^` applied to something that is not a reference (or to NULL)",
    RefNotAVariable = "E0181": "`REF()` of something that has no address of its own (a bit, a subrange variable), or, as an initial value, of a variable without one place for the whole run",

    // ---- calls (checker): E0200–E0249 ----
    UnknownFunction = "E0200": "a call of something that is not a function or function block",
    WrongArgumentCount = "E0201": "a call with too many or too few arguments",
    NoSuchParameter = "E0202": "a call naming a parameter the callee does not have",
    DuplicateArgument = "E0203": "a parameter given twice in one call",
    MixedArguments = "E0204": "formal and informal arguments mixed in one call",
    NotAnOutput = "E0205": "`=>` used with a parameter that is not an output",
    InOutNotVariable = "E0206": "a VAR_IN_OUT argument that is not a variable",
    MissingInOut = "E0207": "a VAR_IN_OUT parameter not given in a call",
    FbCalledAsFunction = "E0208": "a function block instance used inside an expression",
    FunctionBlockInFunction = "E0209": "a function block instance declared in a FUNCTION",
    ProgramCalled = "E0210": "a PROGRAM called like a function block",
    NoReturnValue = "E0211": "a FUNCTION without a result type used in an expression",

    // ---- running: E0300–E0349 ----
    UnknownSetVariable = "E0300": "`--set`, `--set-at` or `--trace` names a variable the program does not have (or, for `--trace`, one that is not a single value)",
    BadSetValue = "E0301": "`--set` or `--set-at` gives a value that does not fit the variable",
    ProgramTooLarge = "E0302": "the program needs more memory than the simulator allows",
    BadCycleTime = "E0303": "a scan cycle time outside 1 ms to 1 minute",
    FileNotOpened = "E0304": "a file that cannot be opened (unreadable, malformed, or not a project, PLCopen XML, PNML or ST file)",
    ProgramSkipped = "E0305": "the PROGRAM asked for was left out when its file was imported",
    PlantMismatch = "E0306": "a plant PROGRAM whose inputs or outputs do not match the controller's variables",

    // ---- ladder diagrams: E0400–E0449 ----
    LadderOpenCircuit = "E0400": "a ladder element that no power path reaches, or that leads nowhere",
    LadderShortCircuit = "E0401": "a coil with no condition before it (wired straight to the rail)",
    LadderAmbiguousBranch = "E0402": "a branch that starts or ends inside another branch (not series-parallel)",
    LadderMissingOperand = "E0403": "a contact, coil or block pin without an operand",
    LadderBadOperand = "E0404": "an operand that is not a variable, member, element or direct address",
    LadderUnknownBlock = "E0405": "a block type that is neither standard nor a POU of the project",
    LadderMissingInstance = "E0406": "a function block in a rung without an instance variable",
    LadderEdgeCoilShared = "E0407": "an edge coil sharing its rung with another coil",
    LadderAfterCoil = "E0408": "an element after a coil, jump or return in the same row",
    LadderStrayCovered = "E0409": "a covered cell with no block above it",
    LadderBadJump = "E0410": "a jump to an unknown label or backwards",
    LadderBadGrid = "E0411": "a rung whose rows differ in length or whose block leaves the grid",
    LadderUnknownPin = "E0412": "a block pin the block type does not have, a pin given twice, or a pin that is the block's power input",
    LadderPinType = "E0413": "a block pin operand whose type does not fit the pin",
    LadderMissingPin = "E0414": "a block input or VAR_IN_OUT that the block needs but does not get",
    LadderBadWiredPin = "E0415": "a wired block input outside the block's rows, sharing a row, with an operand too, or not BOOL",
    LadderBadPowerPin = "E0416": "a block power input or output that cannot carry the rung's power (not BOOL, or ENO without EN)",
    LadderInstanceType = "E0417": "a block instance declared with another type, or an instance given to a FUNCTION",
    LadderUndeclaredOperand = "E0418": "a ladder operand naming a variable that is not declared",
    NetworkNotRunnable = "E0420": "an element of an LD or FBD network (drawn at its own positions) that cannot be run",

    // ---- Petri nets: E0500–E0549 ----
    PetriDuplicateId = "E0500": "two elements of a Petri net share one id",
    PetriBadArc = "E0501": "an arc that does not join a place and a transition, or has weight 0",
    PetriDuplicateArc = "E0502": "two arcs in the same direction between one place and one transition",
    PetriBadGuard = "E0503": "a transition guard or emergency condition that is not one ST expression",
    PetriBadActions = "E0504": "place actions, a prologue or an epilogue that are not ST statements",
    PetriNotCovered = "E0505": "places that no state-machine component covers (CASE OF code needs them covered)",
    PetriProcessTokens = "E0506": "a process (state-machine component) that does not hold exactly one token",
    PetriDuplicateLabel = "E0507": "two places of one process with the same CASE label",
    PetriBadProcess = "E0508": "a declared process that is not a state-machine component of the net",
    PetriBadEmergency = "E0509": "an emergency place that is not a place of the net",
    PetriBadMacroPlace = "E0510": "a macro-place naming an unknown place, or a place inside two macro-places",
    PetriArcWeight = "E0511": "an arc of weight other than 1 touching a process's places",
    PetriLabelRange = "E0512": "a CASE label outside the INT range",
    PetriFlagsAmbiguous = "E0513": "a place where flag-style code cannot tell two shared transitions apart",
    PetriSourceTransition = "E0514": "a transition without input places",
    PetriBadName = "E0515": "a POU, process or step variable name that is not an identifier",
    PnmlInvalid = "E0516": "a PNML file that cannot be read as a place/transition net",
    PetriEmptyNet = "E0517": "a Petri net without places",

    // ---- textual SFC (crate::sfc): E0550–E0579 ----
    SfcUnknownStep = "E0550": "a transition names a step that is not declared",
    SfcDuplicateName = "E0551": "a step, transition or action name declared twice, or also declared as a variable",
    SfcSecondInitialStep = "E0552": "a second INITIAL_STEP in one SFC network",
    SfcNoInitialStep = "E0553": "an SFC network (or SFC body) without an INITIAL_STEP",
    SfcUnknownAction = "E0554": "an action association naming neither an ACTION nor a variable",
    SfcMissingDuration = "E0555": "a timed qualifier (L, D, SD, DS, SL) without a duration",
    SfcUnexpectedDuration = "E0556": "a duration given to a qualifier that takes none (N, R, S, P, P1, P0)",
    SfcUnknownQualifier = "E0557": "an action qualifier that is not N, R, S, P, P1, P0, L, D, SD, DS or SL",
    SfcConditionNotBool = "E0558": "a transition condition that is not BOOL",
    SfcDurationNotTime = "E0559": "an action duration that is not a TIME",
    SfcReadOnly = "E0560": "an assignment to a step flag (S.X, S.T) or to an action's Q or A",
    SfcNotAllowedHere = "E0561": "an SFC body in a FUNCTION, or statements mixed with steps and transitions",
    SfcReservedName = "E0562": "a type or POU named like the SFC runtime's step type (SFC_STEP)",
    SfcUnnamedTransitionBody = "E0563": "a transition written with statements but without a name to assign",
    SfcStepListedTwice = "E0564": "a step listed twice in one FROM or TO list",
    SfcBooleanActionNotBool = "E0565": "a boolean action whose variable is not BOOL",
    SfcReturnInAction = "E0566": "RETURN inside an ACTION or a transition body",

    // ---- Instruction List (syntax and crate::il): E0580–E0589 ----
    IlUnknownOperator = "E0580": "an IL line whose operator is neither an IL operator nor a function",
    IlBadInstruction = "E0581": "an IL instruction with a missing, extra or wrong operand or modifier",
    IlUndefinedLabel = "E0582": "an IL jump to a label the body does not define, or a label defined twice",
    IlNoCurrentResult = "E0583": "an IL instruction that needs the current result where none is loaded",
    IlResultType = "E0584": "an IL current result of a type the trainer cannot carry there",

    // ---- configurations, resources and tasks: E0620–E0639 ----
    UnsupportedConfiguration = "E0620": "a VAR_ACCESS block, or a second CONFIGURATION in one program",
    UnknownTask = "E0621": "a program instance WITH a task its resource does not declare",
    NotAProgramType = "E0622": "a program instance whose type is not a PROGRAM",
    BadTaskSetting = "E0623": "a task INTERVAL that is not a constant TIME above zero, a PRIORITY that is not a constant 0 to 9999, or a SINGLE that is not a BOOL variable",
    BadProgramConnection = "E0624": "a program connection naming no input or output of the program, or a variable of another type",
    BadConfigVar = "E0625": "a VAR_CONFIG entry whose path names no variable, whose type is not the variable's, whose address does not complete an incomplete address (`%Q*`), or whose initial value that variable cannot take",

    // ---- warnings: W0001– ----
    UnusedVariable = "W0001": "a variable that is declared but never used",
    UnreachableCode = "W0002": "a statement that can never run",
    ImplicitNarrowing = "W0003": "a value that may not fit where it is stored",
    CaseWithoutMatch = "W0004": "a CASE label that can never match the selector's type",
    LadderEnableFromRail = "W0005": "a ladder block whose enable is tied straight to the rail",
    LadderDuplicateCoil = "W0006": "two coils writing the same variable in one ladder POU",
    LadderPinFromRail = "W0007": "a wired block input tied straight to the rail (always TRUE)",
    PetriGuardConflict = "W0010": "transitions leaving one place, with the same priority, whose guards may both hold",
    PetriDeadlock = "W0011": "a reachable marking of a Petri net where no transition can fire (guards ignored)",
    PetriDeadTransition = "W0012": "a Petri net transition that can never fire (guards ignored)",
    PetriAnalysisIncomplete = "W0013": "the Petri net has more reachable markings than the analysis budget",
    PetriPriorityIgnored = "W0014": "transitions competing for one token but decided by different Petri net processes, where priorities cannot choose",
    // textual SFC warnings: W0020–W0029
    SfcUnreachableStep = "W0020": "an SFC step that can never become active",
    SfcUnsafe = "W0021": "an SFC transition that can activate a step that is already active (unsafe SFC)",
    SfcDeadTransition = "W0022": "an SFC transition whose source steps are never active together",
    SfcUnusedAction = "W0023": "an ACTION that no step uses",
    SfcTransitionNotAssigned = "W0024": "a transition body that never assigns the transition's name",
    SfcSamePriority = "W0025": "transitions leaving the same step with the same PRIORITY (source order decides)",
    VariableShadowsEnumValue = "W0030": "a name that is both a variable and a value of the enumeration expected there (read as the value)",
    ImportChanged = "W0031": "part of an imported file that was skipped or changed to fit the trainer",
    FunctionInputWritten = "W0032": "a FUNCTION writes one of its inputs (only its own copy changes)",
    SceneUnknownVariable = "W0033": "a widget of the plant's scene bound to a variable the program does not have",
}

impl std::fmt::Display for Code {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

impl Serialize for Code {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.as_str())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashSet;

    #[test]
    fn codes_are_unique_and_well_formed() {
        let mut seen = HashSet::new();
        for code in Code::all() {
            let s = code.as_str();
            assert!(seen.insert(s), "duplicate code {s}");
            assert_eq!(s.len(), 5, "{s}");
            assert!(s.starts_with('E') || s.starts_with('W'), "{s}");
            assert!(!code.title().is_empty());
        }
    }
}
