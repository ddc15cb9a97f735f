# The top-level command: help, version, usage errors.
. tests/e2e/lib.sh

expect "help lists commands"          0 '~commands:' '' -- --help
expect "version"                      0 'shadecalc 0.1.0' '' -- --version
expect "no command is a usage error"  2 '' '~usage: shadecalc COMMAND' --
expect "unknown command is named"     2 '' "error: unknown command 'frobnicate' (see 'shadecalc --help')" -- frobnicate
