//! The standard function blocks (IEC 61131-3 §2.5.2.3), written in ST and compiled with the
//! user's program so they run on the one VM. Their behaviour follows docs/semantics.md; timers
//! read the virtual clock through the system variable `SYS_CLOCK`.
//!
//! Documented surprises: `F_TRIG` called first with `CLK = FALSE` gives `Q = TRUE` (the
//! standard body, since its memory starts FALSE); counters let reset/load win over
//! counting, and `CV` keeps counting past `PV` up to the limit of INT.

/// `CTU_T`, `CTD_T` and `CTUD_T` of edition 3 for the counter type `T` with its limits:
/// `CTU`, `CTD` and `CTUD` with `PV` and `CV` of that type.
macro_rules! typed_counters {
    ($t:literal, $max:literal, $min:literal) => {
        concat!(
            "\nFUNCTION_BLOCK CTU_",
            $t,
            "\n",
            "VAR_INPUT CU : BOOL; R : BOOL; PV : ",
            $t,
            "; END_VAR\n",
            "VAR_OUTPUT Q : BOOL; CV : ",
            $t,
            "; END_VAR\n",
            "VAR CU_M : BOOL; END_VAR\n",
            "IF R THEN\n    CV := 0;\n",
            "ELSIF CU AND NOT CU_M AND CV < ",
            $max,
            " THEN\n    CV := CV + 1;\nEND_IF;\n",
            "CU_M := CU;\nQ := CV >= PV;\nEND_FUNCTION_BLOCK\n",
            "\nFUNCTION_BLOCK CTD_",
            $t,
            "\n",
            "VAR_INPUT CD : BOOL; LD : BOOL; PV : ",
            $t,
            "; END_VAR\n",
            "VAR_OUTPUT Q : BOOL; CV : ",
            $t,
            "; END_VAR\n",
            "VAR CD_M : BOOL; END_VAR\n",
            "IF LD THEN\n    CV := PV;\n",
            "ELSIF CD AND NOT CD_M AND CV > ",
            $min,
            " THEN\n    CV := CV - 1;\nEND_IF;\n",
            "CD_M := CD;\nQ := CV <= 0;\nEND_FUNCTION_BLOCK\n",
            "\nFUNCTION_BLOCK CTUD_",
            $t,
            "\n",
            "VAR_INPUT CU : BOOL; CD : BOOL; R : BOOL; LD : BOOL; PV : ",
            $t,
            "; END_VAR\n",
            "VAR_OUTPUT QU : BOOL; QD : BOOL; CV : ",
            $t,
            "; END_VAR\n",
            "VAR CU_M : BOOL; CD_M : BOOL; END_VAR\n",
            "IF R THEN\n    CV := 0;\nELSIF LD THEN\n    CV := PV;\n",
            "ELSIF NOT (CU AND NOT CU_M AND CD AND NOT CD_M) THEN\n",
            "    IF CU AND NOT CU_M AND CV < ",
            $max,
            " THEN\n        CV := CV + 1;\n",
            "    ELSIF CD AND NOT CD_M AND CV > ",
            $min,
            " THEN\n        CV := CV - 1;\n",
            "    END_IF;\nEND_IF;\n",
            "CU_M := CU;\nCD_M := CD;\nQU := CV >= PV;\nQD := CV <= 0;\nEND_FUNCTION_BLOCK\n",
        )
    };
}

/// The standard blocks, each written once.
macro_rules! blocks {
    () => {
        r#"
FUNCTION_BLOCK R_TRIG
VAR_INPUT CLK : BOOL; END_VAR
VAR_OUTPUT Q : BOOL; END_VAR
VAR M : BOOL; END_VAR
Q := CLK AND NOT M;
M := CLK;
END_FUNCTION_BLOCK

FUNCTION_BLOCK F_TRIG
VAR_INPUT CLK : BOOL; END_VAR
VAR_OUTPUT Q : BOOL; END_VAR
VAR M : BOOL; END_VAR
Q := NOT CLK AND NOT M;
M := NOT CLK;
END_FUNCTION_BLOCK

FUNCTION_BLOCK SR
VAR_INPUT S1 : BOOL; R : BOOL; END_VAR
VAR_OUTPUT Q1 : BOOL; END_VAR
Q1 := S1 OR (NOT R AND Q1);
END_FUNCTION_BLOCK

FUNCTION_BLOCK RS
VAR_INPUT S : BOOL; R1 : BOOL; END_VAR
VAR_OUTPUT Q1 : BOOL; END_VAR
Q1 := NOT R1 AND (S OR Q1);
END_FUNCTION_BLOCK

FUNCTION_BLOCK CTU
VAR_INPUT CU : BOOL; R : BOOL; PV : INT; END_VAR
VAR_OUTPUT Q : BOOL; CV : INT; END_VAR
VAR CU_M : BOOL; END_VAR
IF R THEN
    CV := 0;
ELSIF CU AND NOT CU_M AND CV < 32767 THEN
    CV := CV + 1;
END_IF;
CU_M := CU;
Q := CV >= PV;
END_FUNCTION_BLOCK

FUNCTION_BLOCK CTD
VAR_INPUT CD : BOOL; LD : BOOL; PV : INT; END_VAR
VAR_OUTPUT Q : BOOL; CV : INT; END_VAR
VAR CD_M : BOOL; END_VAR
IF LD THEN
    CV := PV;
ELSIF CD AND NOT CD_M AND CV > -32768 THEN
    CV := CV - 1;
END_IF;
CD_M := CD;
Q := CV <= 0;
END_FUNCTION_BLOCK

FUNCTION_BLOCK CTUD
VAR_INPUT CU : BOOL; CD : BOOL; R : BOOL; LD : BOOL; PV : INT; END_VAR
VAR_OUTPUT QU : BOOL; QD : BOOL; CV : INT; END_VAR
VAR CU_M : BOOL; CD_M : BOOL; END_VAR
IF R THEN
    CV := 0;
ELSIF LD THEN
    CV := PV;
ELSIF NOT (CU AND NOT CU_M AND CD AND NOT CD_M) THEN
    IF CU AND NOT CU_M AND CV < 32767 THEN
        CV := CV + 1;
    ELSIF CD AND NOT CD_M AND CV > -32768 THEN
        CV := CV - 1;
    END_IF;
END_IF;
CU_M := CU;
CD_M := CD;
QU := CV >= PV;
QD := CV <= 0;
END_FUNCTION_BLOCK

FUNCTION_BLOCK TON
VAR_INPUT IN : BOOL; PT : TIME; END_VAR
VAR_OUTPUT Q : BOOL; ET : TIME; END_VAR
VAR StartTime : TIME; Running : BOOL; END_VAR
IF IN THEN
    IF NOT Running THEN
        Running := TRUE;
        StartTime := SYS_CLOCK;
    END_IF;
    ET := SYS_CLOCK - StartTime;
    IF ET >= PT THEN
        ET := PT;
        Q := TRUE;
    ELSE
        Q := FALSE;
    END_IF;
ELSE
    Running := FALSE;
    Q := FALSE;
    ET := T#0s;
END_IF;
END_FUNCTION_BLOCK

FUNCTION_BLOCK TOF
VAR_INPUT IN : BOOL; PT : TIME; END_VAR
VAR_OUTPUT Q : BOOL; ET : TIME; END_VAR
VAR StartTime : TIME; Running : BOOL; END_VAR
IF IN THEN
    Running := FALSE;
    Q := TRUE;
    ET := T#0s;
ELSIF Q THEN
    IF NOT Running THEN
        Running := TRUE;
        StartTime := SYS_CLOCK;
    END_IF;
    ET := SYS_CLOCK - StartTime;
    IF ET >= PT THEN
        ET := PT;
        Q := FALSE;
        Running := FALSE;
    END_IF;
END_IF;
END_FUNCTION_BLOCK

FUNCTION_BLOCK TP
VAR_INPUT IN : BOOL; PT : TIME; END_VAR
VAR_OUTPUT Q : BOOL; ET : TIME; END_VAR
VAR StartTime : TIME; IN_M : BOOL; END_VAR
IF NOT Q AND IN AND NOT IN_M AND ET = T#0s THEN
    Q := TRUE;
    StartTime := SYS_CLOCK;
END_IF;
IF Q THEN
    ET := SYS_CLOCK - StartTime;
    IF ET >= PT THEN
        ET := PT;
        Q := FALSE;
    END_IF;
ELSIF NOT IN THEN
    ET := T#0s;
END_IF;
IN_M := IN;
END_FUNCTION_BLOCK

FUNCTION_BLOCK RTO
VAR_INPUT IN : BOOL; R : BOOL; PT : TIME; END_VAR
VAR_OUTPUT Q : BOOL; ET : TIME; END_VAR
VAR LastTime : TIME; Running : BOOL; END_VAR
IF R THEN
    ET := T#0s;
    Running := FALSE;
ELSIF IN THEN
    IF Running THEN
        ET := ET + (SYS_CLOCK - LastTime);
    END_IF;
    Running := TRUE;
    LastTime := SYS_CLOCK;
    IF ET > PT THEN
        ET := PT;
    END_IF;
ELSE
    Running := FALSE;
END_IF;
Q := ET >= PT;
END_FUNCTION_BLOCK
"#
    };
}

/// The date and time functions of edition 3 (IEC 61131-3 ed. 3, table 36): CONCAT_DATE,
/// CONCAT_TOD, CONCAT_DT, CONCAT_DATE_TOD, SPLIT_DATE, SPLIT_TOD, SPLIT_DT and
/// DAY_OF_WEEK (0 is Sunday). Dates convert through their days since 1970-01-01 with the
/// proleptic Gregorian calendar (the days-from-civil algorithm).
macro_rules! date_functions {
    () => {
        r#"
FUNCTION CONCAT_DATE : DATE
VAR_INPUT YEAR : INT; MONTH : INT; DAY : INT; END_VAR
VAR y, m, era, yoe, doy, doe : LINT; END_VAR
y := INT_TO_LINT(YEAR);
m := INT_TO_LINT(MONTH);
IF m <= 2 THEN
    y := y - 1;
    doy := (153 * (m + 9) + 2) / 5 + INT_TO_LINT(DAY) - 1;
ELSE
    doy := (153 * (m - 3) + 2) / 5 + INT_TO_LINT(DAY) - 1;
END_IF;
IF y >= 0 THEN era := y / 400; ELSE era := (y - 399) / 400; END_IF;
yoe := y - era * 400;
doe := yoe * 365 + yoe / 4 - yoe / 100 + doy;
CONCAT_DATE := LINT_TO_DATE((era * 146097 + doe - 719468) * 86400);
END_FUNCTION

FUNCTION CONCAT_TOD : TOD
VAR_INPUT HOUR : INT; MINUTE : INT; SECOND : INT; MILLISECOND : INT; END_VAR
CONCAT_TOD := LINT_TO_TOD(((INT_TO_LINT(HOUR) * 60 + INT_TO_LINT(MINUTE)) * 60
    + INT_TO_LINT(SECOND)) * 1000 + INT_TO_LINT(MILLISECOND));
END_FUNCTION

FUNCTION CONCAT_DATE_TOD : DT
VAR_INPUT DATE1 : DATE; TOD1 : TOD; END_VAR
CONCAT_DATE_TOD := LINT_TO_DT(DATE_TO_LINT(DATE1)) + (TOD1 - TOD#00:00:00);
END_FUNCTION

FUNCTION CONCAT_DT : DT
VAR_INPUT YEAR : INT; MONTH : INT; DAY : INT; HOUR : INT; MINUTE : INT; SECOND : INT;
    MILLISECOND : INT; END_VAR
CONCAT_DT := CONCAT_DATE_TOD(CONCAT_DATE(YEAR, MONTH, DAY),
    CONCAT_TOD(HOUR, MINUTE, SECOND, MILLISECOND));
END_FUNCTION

FUNCTION SPLIT_DATE
VAR_INPUT IN : DATE; END_VAR
VAR_OUTPUT YEAR : INT; MONTH : INT; DAY : INT; END_VAR
VAR secs, z, era, doe, yoe, y, doy, mp, m : LINT; END_VAR
secs := DATE_TO_LINT(IN);
z := secs / 86400;
IF secs < 0 AND secs MOD 86400 <> 0 THEN z := z - 1; END_IF;
z := z + 719468;
IF z >= 0 THEN era := z / 146097; ELSE era := (z - 146096) / 146097; END_IF;
doe := z - era * 146097;
yoe := (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
y := yoe + era * 400;
doy := doe - (365 * yoe + yoe / 4 - yoe / 100);
mp := (5 * doy + 2) / 153;
DAY := LINT_TO_INT(doy - (153 * mp + 2) / 5 + 1);
IF mp < 10 THEN m := mp + 3; ELSE m := mp - 9; END_IF;
IF m <= 2 THEN y := y + 1; END_IF;
MONTH := LINT_TO_INT(m);
YEAR := LINT_TO_INT(y);
END_FUNCTION

FUNCTION SPLIT_TOD
VAR_INPUT IN : TOD; END_VAR
VAR_OUTPUT HOUR : INT; MINUTE : INT; SECOND : INT; MILLISECOND : INT; END_VAR
VAR ms : LINT; END_VAR
ms := TOD_TO_LINT(IN);
HOUR := LINT_TO_INT(ms / 3600000);
MINUTE := LINT_TO_INT((ms / 60000) MOD 60);
SECOND := LINT_TO_INT((ms / 1000) MOD 60);
MILLISECOND := LINT_TO_INT(ms MOD 1000);
END_FUNCTION

FUNCTION SPLIT_DT
VAR_INPUT IN : DT; END_VAR
VAR_OUTPUT YEAR : INT; MONTH : INT; DAY : INT; HOUR : INT; MINUTE : INT; SECOND : INT;
    MILLISECOND : INT; END_VAR
SPLIT_DATE(IN := DT_TO_DATE(IN), YEAR => YEAR, MONTH => MONTH, DAY => DAY);
SPLIT_TOD(IN := DT_TO_TOD(IN), HOUR => HOUR, MINUTE => MINUTE, SECOND => SECOND,
    MILLISECOND => MILLISECOND);
END_FUNCTION

FUNCTION DAY_OF_WEEK : INT
VAR_INPUT IN : DATE; END_VAR
VAR secs, days : LINT; END_VAR
secs := DATE_TO_LINT(IN);
days := secs / 86400;
IF secs < 0 AND secs MOD 86400 <> 0 THEN days := days - 1; END_IF;
days := (days + 4) MOD 7;
IF days < 0 THEN days := days + 7; END_IF;
DAY_OF_WEEK := LINT_TO_INT(days);
END_FUNCTION
"#
    };
}

/// The prelude's source text: the blocks above, the typed counters and the date functions.
pub const SOURCE: &str = concat!(
    blocks!(),
    date_functions!(),
    typed_counters!("INT", "32767", "-32768"),
    typed_counters!("DINT", "2147483647", "-2147483648"),
    typed_counters!("LINT", "9223372036854775807", "-9223372036854775808"),
    typed_counters!("UDINT", "4294967295", "0"),
    typed_counters!("ULINT", "18446744073709551615", "0"),
);
