//! The inputs that once crashed or hung the engine (`plc_tests::hostile`), natively, on a
//! thread with a 1 MiB stack like the browser's wasm stack.

#[test]
fn hostile_inputs_give_located_errors_on_a_small_stack() {
    let failures = std::thread::Builder::new()
        .stack_size(1 << 20)
        .spawn(plc_tests::hostile::check_all)
        .expect("a thread")
        .join()
        .expect("no input may overflow the stack");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
