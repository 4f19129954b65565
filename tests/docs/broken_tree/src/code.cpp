// A fixture of tests/docs: citations that do not resolve. guide.md 2 and
// guide.md (a) do; guide.md 3.1 does not, nor does docs/guide.md section 7.
// guide.md (b) does not, nor does guide.md "Third part".
// style.md 10 is not in this tree.
const char* theory =
    "../"
    "shared/docs/theory.md";
const char* notes =
    "/wor"
    "k/notes.md";
// A seed named without its "../": shared/seeds/003.
