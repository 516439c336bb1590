"""What every glyphfair command test checks the same way: the error contract (the expected
exit code, one line on stderr saying what went wrong) and the closing tally."""


def error_problem(result, code, text):
    """None when `result` exited with `code` and said `text` in exactly one stderr line, else
    what was wrong."""
    lines = [l for l in result.stderr.splitlines() if l.strip()]
    if result.returncode == code and len(lines) == 1 and text in lines[0]:
        return None
    return f"exit {result.returncode}, stderr {result.stderr!r}"


def finish(failures):
    """Print the failures and a tally; the exit status for the test."""
    for f in failures:
        print("FAIL:", f)
    print(f"{len(failures)} failures")
    return 1 if failures else 0
