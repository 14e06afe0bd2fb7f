use super::*;

fn code(r: Result<impl std::fmt::Debug, LitError>) -> &'static str {
    match r {
        Ok(v) => panic!("expected an error, got {v:?}"),
        Err((c, _)) => c.as_str(),
    }
}

const MS: i64 = 1_000_000;
const S: i64 = 1_000 * MS;

#[test]
fn integers() {
    assert_eq!(parse_integer("123_456"), Ok(123_456));
    assert_eq!(parse_integer("2#1110_0000"), Ok(224));
    assert_eq!(parse_integer("8#377"), Ok(255));
    assert_eq!(parse_integer("16#e5"), Ok(229));
    assert_eq!(parse_integer("16#FE"), Ok(254));
    assert_eq!(parse_integer("18446744073709551615"), Ok(i128::from(u64::MAX)));
    assert_eq!(code(parse_integer("18446744073709551616")), "E0012");
    assert_eq!(code(parse_integer("2#102")), "E0004");
    assert_eq!(code(parse_integer("7#1")), "E0004");
    assert_eq!(code(parse_integer("1__0")), "E0004");
    assert_eq!(code(parse_integer("16#")), "E0004");
}

#[test]
fn reals() {
    assert_eq!(parse_real("1_2.5_5"), Ok(12.55));
    assert_eq!(parse_real("3.14159_26").map(|v| (v * 1e7).round()), Ok(31_415_926.0));
    assert_eq!(parse_real("1.234e-6"), Ok(1.234e-6));
    assert_eq!(parse_real("1.0E+3"), Ok(1000.0));
    assert_eq!(code(parse_real("1.0e999")), "E0004");
}

#[test]
fn strings_and_escapes() {
    assert_eq!(parse_string("''"), Ok(vec![]));
    assert_eq!(parse_string("'$''"), Ok(b"'".to_vec()));
    assert_eq!(parse_string("'$R$L'"), Ok(b"\r\n".to_vec()));
    assert_eq!(parse_string("'$$1.00'"), Ok(b"$1.00".to_vec()));
    assert_eq!(parse_string("'$0A'"), Ok(vec![0x0a]));
    assert_eq!(parse_string("'$C4$CB'"), Ok(vec![0xc4, 0xcb]));
    assert_eq!(parse_string("'$n$N$l$t$T$r$p$P'"), Ok(vec![10, 10, 10, 9, 9, 13, 12, 12]));
    assert_eq!(parse_string("'\"'"), Ok(b"\"".to_vec()));
    assert_eq!(parse_string("'$\"'"), Ok(b"\"".to_vec()));
    assert_eq!(parse_string("'Ä'"), Ok("Ä".as_bytes().to_vec()));
    assert_eq!(code(parse_string("'$Q'")), "E0008");
    assert_eq!(code(parse_string("'$4'")), "E0008");
    assert_eq!(code(parse_string("'$")), "E0008");
    // Unterminated (the lexer reports it): the text so far is decoded.
    assert_eq!(parse_string("'abc"), Ok(b"abc".to_vec()));
}

#[test]
fn wide_strings() {
    assert_eq!(parse_wstring("\"OK\""), Ok(vec![79, 75]));
    assert_eq!(parse_wstring("\"$00C4$\"\""), Ok(vec![0xc4, 34]));
    assert_eq!(parse_wstring("\"'\""), Ok(vec![39]));
    assert_eq!(parse_wstring("\"Ä\""), Ok(vec![0xc4]));
    assert_eq!(code(parse_wstring("\"$0A\"")), "E0008");
}

#[test]
fn durations() {
    assert_eq!(parse_duration("T#5s"), Ok(5 * S));
    assert_eq!(parse_duration("t#-14ms"), Ok(-14 * MS));
    assert_eq!(
        parse_duration("T#5d14h12m18s3.5ms"),
        Ok(((5 * 24 + 14) * 3600 + 12 * 60 + 18) * S + 3 * MS + 500_000)
    );
    assert_eq!(parse_duration("TIME#14.7h"), Ok(14 * 3600 * S + 42 * 60 * S));
    assert_eq!(parse_duration("time#25h15m"), Ok((25 * 3600 + 15 * 60) * S));
    assert_eq!(parse_duration("T#1h_30m"), Ok(90 * 60 * S));
    assert_eq!(parse_duration("T#1_000ms"), Ok(S));
    assert_eq!(parse_duration("LT#1us5ns"), Ok(1005));
    assert_eq!(parse_duration("T#1.5S"), Ok(1500 * MS));
    assert_eq!(parse_duration("T#0.1ns"), Ok(0));
    assert_eq!(parse_duration("T#0.6ns"), Ok(1));
    assert_eq!(parse_duration("T#+2m"), Ok(120 * S));
    for bad in [
        "T#1h75m",
        "T#1m60s",
        "T#1s1000ms",
        "T#1.5h3m",
        "T#5",
        "T#",
        "T#3m2h",
        "T#1s1s",
        "T#5x",
        "T#106752d",
    ] {
        assert_eq!(code(parse_duration(bad)), "E0005", "{bad}");
    }
}

#[test]
fn dates_and_times() {
    assert_eq!(parse_date("D#1970-01-01"), Ok(0));
    // DATE and DT count microseconds.
    let day = 86_400 * S / 1000;
    assert_eq!(parse_date("DATE#2006-03-20"), Ok(13_227 * day));
    assert_eq!(parse_date("D#2000-03-01"), Ok(11_017 * day));
    assert_eq!(parse_date("D#1969-12-31"), Ok(-day));
    assert_eq!(parse_date("D#2024-02-29"), Ok(19_782 * day));
    assert_eq!(parse_time_of_day("TOD#10:42:23.78"), Ok((10 * 3600 + 42 * 60 + 23) * S + 780 * MS));
    assert_eq!(parse_time_of_day("TIME_OF_DAY#00:00:00"), Ok(0));
    assert_eq!(
        parse_date_time("DT#2006-03-20-10:42:23.78"),
        Ok(13_227 * day + ((10 * 3600 + 42 * 60 + 23) * S + 780 * MS) / 1000)
    );
    // The ends of the range: 0001-01-01 is 719,162 days before 1970-01-01, 9999-12-31
    // 2,932,896 days after it (365 days a year, a leap day every 4 years but 100 but 400).
    assert_eq!(parse_date("D#0001-01-01"), Ok(-719_162 * day));
    assert_eq!(parse_date("D#9999-12-31"), Ok(2_932_896 * day));
    assert_eq!(
        parse_date_time("DT#9999-12-31-23:59:59.999999999"),
        Ok(2_932_897 * day - 1),
        "digits past the microsecond are dropped"
    );
    for bad in ["D#0000-12-31", "D#10000-01-01"] {
        assert_eq!(code(parse_date(bad)), "E0010", "{bad}");
    }
    for bad in ["D#2006-13-01", "D#2023-02-29", "D#2006-04-31", "D#2006-03", "D#2006-00-10"] {
        assert_eq!(code(parse_date(bad)), "E0010", "{bad}");
    }
    for bad in ["TOD#24:00:00", "TOD#10:60:00", "TOD#10:00:61", "TOD#10", "TOD#1:2:3."] {
        assert_eq!(code(parse_time_of_day(bad)), "E0010", "{bad}");
    }
    assert_eq!(code(parse_date_time("DT#2006-03-20")), "E0010");
}

#[test]
fn direct_addresses() {
    use AddressArea::*;
    use AddressSize::*;
    assert_eq!(parse_direct_address("%IX0.0"), Ok((Input, Bit, vec![0, 0])));
    assert_eq!(parse_direct_address("%I0.0"), Ok((Input, Bit, vec![0, 0])));
    assert_eq!(parse_direct_address("%QX1.2"), Ok((Output, Bit, vec![1, 2])));
    assert_eq!(parse_direct_address("%IW4"), Ok((Input, Word, vec![4])));
    assert_eq!(parse_direct_address("%MW6"), Ok((Memory, Word, vec![6])));
    assert_eq!(parse_direct_address("%MD10"), Ok((Memory, DWord, vec![10])));
    assert_eq!(parse_direct_address("%MB3"), Ok((Memory, Byte, vec![3])));
    assert_eq!(parse_direct_address("%ML2"), Ok((Memory, LWord, vec![2])));
    assert_eq!(parse_direct_address("%ib0"), Ok((Input, Byte, vec![0])));
    assert_eq!(parse_direct_address("%I*"), Ok((Input, Bit, vec![])));
    for bad in ["%", "%Z1", "%IY1", "%IX", "%IXa", "%IW99999999999"] {
        assert_eq!(code(parse_direct_address(bad)), "E0009", "{bad}");
    }
    assert_eq!(parse_bit_address("%X3"), Some(3));
    assert_eq!(parse_bit_address("%W3"), None);
}

#[test]
fn type_prefixes() {
    assert_eq!(prefix_class("dint"), Some(PrefixClass::Integer));
    assert_eq!(prefix_class("Color"), None);
    let b = |v| apply_prefix("BOOL", PrefixClass::Bool, v);
    assert_eq!(b(LiteralValue::Int(1)), Ok(LiteralValue::Bool(true)));
    assert_eq!(b(LiteralValue::Int(0)), Ok(LiteralValue::Bool(false)));
    assert_eq!(code(b(LiteralValue::Int(2))), "E0013");
    assert_eq!(
        apply_prefix("LREAL", PrefixClass::Real, LiteralValue::Int(1)),
        Ok(LiteralValue::Real(1.0))
    );
    assert_eq!(code(apply_prefix("INT", PrefixClass::Integer, LiteralValue::Real(1.5))), "E0013");
    assert_eq!(code(apply_prefix("STRING", PrefixClass::String, LiteralValue::Int(1))), "E0013");
}
