# The top-level command: help, version, usage errors.
. tests/e2e/lib.sh

expect "help lists commands"          0 '~commands:' '' -- --help
expect "version"                      0 'shadecalc 0.1.0' '' -- --version
expect "no command is a usage error"  2 '' '~usage: shadecalc COMMAND' --
expect "unknown command is named"     2 '' "error: unknown command 'frobnicate' (see 'shadecalc --help')" -- frobnicate
expect "help COMMAND is the command's help" 0 '~usage: shadecalc eval' '' -- help eval
expect "help of an unknown command"      2 '' "~unknown command 'evl'; did you mean 'eval'?" -- help evl
expect "did you mean a command"          2 '' "error: unknown command 'swep'; did you mean 'sweep'? (see 'shadecalc --help')" -- swep
expect "a command's name is escaped"     2 '' "error: unknown command 'a\\x1b[31m' (see 'shadecalc --help')" -- "$(printf 'a\033[31m')"
