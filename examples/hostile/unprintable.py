"""Hostile: a submission whose error message holds a lone surrogate ('\\udcff', which
Python's json escapes and a UTF-8 reader rejects) and terminal escape sequences that would erase a
line and print a green PASS where report.md is shown with cat or less -R. Expected: the check of
casimir FAILS with that message shown as inert text (\\udcff and \\x1b visible, no escape byte in
any report), and the rest of the submission is checked."""


def casimir(Pi):
    raise RuntimeError("broken \udcff text\x1b[2K\r\x1b[32mPASS\x1b[0m")
