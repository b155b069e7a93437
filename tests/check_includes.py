#!/usr/bin/env python3
"""Every first-party file includes the header of each of the project's own names it uses.

A unity batch compiles several files as one, so a file that uses a name without including its
header builds as long as an earlier file of its batch includes it; another batch size (the release
preset's 8 against the check preset's 32), a build without batches or another compiler then fails.
Compiling each of the ~450 files alone would show it soundly but costs about 20 minutes of CPU
(tests/check_standalone_includes.py does it, for the files a change touched). This check reads the
sources instead, in a second or two:

* every header of core/, devices/, ui/, app/ and tests/ declares names at namespace scope (classes,
  structs, enums, aliases, constants, functions, macros);
* a name declared by exactly one header, and by nothing else anywhere (no member, no local), is that
  header's;
* a file that uses such a name (unqualified or qualified by one of our namespaces, never after `.`,
  `->` or another class's `::`) must have that header among the headers it includes, directly or
  through others.

It knows nothing of third-party names (the shared precompiled header holds the heavy ones in every
build) and little of overloads and templates; what it reports is a real missing include or a name
worth renaming. Usage: check_includes.py [FILE...] (default: the whole tree). Exit 1 on a finding.
"""
import os
import re
import subprocess
import sys
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
FOLDERS = ["core", "devices", "ui", "app", "tests"]
OUR_NAMESPACES = {"lmc", "devices", "ui", "calibration", "figures", "session", "stats", "vis", "cli", "test",
                  "detail"}
KEYWORDS = set("""alignas alignof and asm auto bool break case catch char class const consteval constexpr
constinit const_cast continue co_await co_return co_yield decltype default delete do double dynamic_cast else
enum explicit export extern false float for friend goto if inline int long mutable namespace new noexcept not
nullptr operator or private protected public register reinterpret_cast requires return short signed sizeof
static static_assert static_cast struct switch template this thread_local throw true try typedef typeid
typename union unsigned using virtual void volatile wchar_t while override final""".split())


# Comments, raw strings, strings and character literals (not a digit separator: 1'000).
LITERALS = re.compile(r'//[^\n]*|/\*.*?\*/|\bR"([^(\s]*)\(.*?\)\1"|"(?:\\.|[^"\\\n])*"|(?<!\w)\'(?:\\.|[^\'\\\n])*\'',
                      re.DOTALL)


def strip_code(text):
    """The text with comments, string and character literals blanked (lengths and lines kept)."""
    def blank(m):
        t = m.group()
        if t[0] in "\"'R" and not t.startswith("//"):
            q = '"' if t[0] == "R" else t[0]
            return q + re.sub(r"[^\n]", " ", t[1:-1]) + q if len(t) >= 2 else t
        return re.sub(r"[^\n]", " ", t)
    return LITERALS.sub(blank, text)


INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"', re.MULTILINE)


def resolve_include(name, including):
    for base in (ROOT, including.parent):
        p = (base / name).resolve()
        if p.is_file():
            return p
    return None


def namespace_scope_statements(code):
    """(statement text, at namespace scope?) for each statement or block head of stripped code."""
    stack, start, parens = [], 0, 0
    for m in re.finditer(r"[{}();]", code):
        # Braces and semicolons inside parentheses (`= {}` defaults, for (;;)) end nothing.
        if m.group() in "()":
            parens = max(0, parens + (1 if m.group() == "(" else -1))
            continue
        if parens:
            continue
        head = code[start:m.start()]
        at_ns = all(k == "ns" for k in stack)
        if m.group() == "{":
            kind = "ns" if re.search(r'(\bnamespace\b[\w:\s]*|\bextern\s*"C"\s*)$', head.strip() + " ") or \
                re.search(r"\bnamespace\b[\w:\s]*$", head) else "other"
            yield head, at_ns, "{"
            stack.append(kind)
        elif m.group() == "}":
            if stack:
                stack.pop()
        else:
            yield head, at_ns, ";"
        start = m.end()


DECL_PATTERNS = [
    re.compile(r"\b(?:class|struct|union)\s+(?:\[\[[^\]]*\]\]\s*)?(?:alignas\([^)]*\)\s*)?([A-Za-z_]\w*)\s*(?:final\b\s*)?(?::[^:]|$)"),
    re.compile(r"\benum\s+(?:class\s+|struct\s+)?([A-Za-z_]\w*)"),
    re.compile(r"\busing\s+([A-Za-z_]\w*)\s*="),
    re.compile(r"\b(?:constexpr|const|constinit)\b[^=(){}]*?\b([A-Za-z_]\w*)\s*(?:\[[^\]]*\]\s*)?(?:=|$)"),
]
# Words after which `name(` is a call, not a declaration of name.
STATEMENT_WORDS = {"throw", "return", "else", "new", "delete", "co_return", "co_yield", "case", "do", "not",
                   "and", "or", "sizeof", "alignof", "decltype", "noexcept", "typeid"}
FUNCTION = re.compile(r"(?:^|[\s*&>:])([A-Za-z_]\w*)\s*\(")


def declared_names(code, namespace_only):
    """Names declared by the stripped code (at namespace scope only, or anywhere)."""
    names = set()
    for head, at_ns, _ in namespace_scope_statements(code):
        if namespace_only and not at_ns:
            continue
        text = " ".join(re.sub(r"^[ \t]*#.*$", "", head, flags=re.MULTILINE).split())
        text = re.sub(r"^(?:template\s*<[^;{}]*?>\s*)+", "", text)
        if not text or text.startswith(("return", "namespace", "case", "default")):
            continue
        # A function's parameters (`const Options& options = {}`) are not the namespace's names.
        flat = text
        while True:
            inner = re.sub(r"\([^()]*\)", "()", flat)
            if inner == flat:
                break
            flat = inner
        for pat in DECL_PATTERNS:
            for m in pat.finditer(flat):
                if m.group(1) not in KEYWORDS:
                    names.add(m.group(1))
        m = FUNCTION.search(text)
        if m and m.group(1) not in KEYWORDS and not text.startswith(("using", "typedef")):
            before = text[:m.start(1)].strip()
            # A declaration has a return type (or is a constructor) before the name.
            last = re.findall(r"[A-Za-z_]\w*|\S", before)[-1] if before else ""
            if before and not re.search(r"[=,(?:!|+\-/%^~<]$", before) and last not in STATEMENT_WORDS:
                names.add(m.group(1))
    return names


# A local, member or parameter: a type (a built-in, ours in CamelCase, std::…) then a name. Not
# `a * b;`, which is arithmetic here far more often than a declaration.
TYPE = (r"(?:\b(?:auto|bool|char|short|int|long|float|double|unsigned|signed|\w+_t)\b"
        r"|\b(?:\w+::)*[A-Z]\w*(?:<[^;{}()]*>)?|\b(?:\w+::)+\w+(?:<[^;{}()]*>)?)")
LOCAL = re.compile(TYPE + r"(?:\s*const)?\s*[&*]*\s*\b([A-Za-z_]\w*)\s*(?:=|\{|;|,|\)|\[|:(?!:))")


def names_anywhere(code):
    """Names the code declares at any scope: members, locals, parameters, lambdas."""
    names = declared_names(code, namespace_only=False)
    for m in LOCAL.finditer(code):
        names.add(m.group(1))
    for m in re.finditer(r"\btemplate\s*<([^;{}]*?)>\s*(?:class|struct|using|[A-Za-z_])", code):
        names |= set(re.findall(r"\b(?:typename|class)\s*(?:\.\.\.)?\s*([A-Za-z_]\w*)", m.group(1)))
    for m in re.finditer(r"\benum\b[^{;()]*\{([^}]*)\}", code):
        names |= set(re.findall(r"(?:^|,)\s*([A-Za-z_]\w*)", m.group(1)))
    for m in re.finditer(r"\bauto\s*&{0,2}\s*\[([^\]]*)\]", code):
        names |= set(re.findall(r"[A-Za-z_]\w*", m.group(1)))
    return names


def forward_declared(code):
    """Names a header only declares (`struct X;`): they satisfy a use, but own nothing."""
    return set(re.findall(r"\b(?:class|struct|union)\s+([A-Za-z_]\w*)\s*;", code)) | \
        set(re.findall(r"\benum\s+(?:class\s+|struct\s+)?([A-Za-z_]\w*)\s*:\s*[\w:]+\s*;", code))


def namespaces(code):
    return {n for m in re.findall(r"\bnamespace\s+([\w:]+)", code) for n in m.split("::")}


def macros(text):
    return set(re.findall(r"^\s*#\s*define\s+([A-Za-z_]\w*)", text, re.MULTILINE))


IDENTIFIER = re.compile(r"[A-Za-z_]\w*")
PREPROCESSOR_LINE = re.compile(r"^[ \t]*#.*$", re.MULTILINE)
AFTER_MEMBER_ACCESS = re.compile(r"(\.|->)\s*$")
AFTER_QUALIFIER = re.compile(r"([A-Za-z_]\w*)\s*::\s*$")
AFTER_SCOPE = re.compile(r"::\s*$")


def used_names(code, wanted=None):
    """(name, line) of identifiers used as our own: not after '.', '->' or a foreign '::'.
    `wanted(name)`, when given, skips the others before any of that work (most identifiers)."""
    code = PREPROCESSOR_LINE.sub("", code)
    line, counted_to = 1, 0
    for m in IDENTIFIER.finditer(code):
        name = m.group()
        if name in KEYWORDS or (wanted is not None and not wanted(name)):
            continue
        before = code[max(0, m.start() - 64):m.start()]
        if AFTER_MEMBER_ACCESS.search(before):
            continue
        q = AFTER_QUALIFIER.search(before)
        if q and q.group(1) not in OUR_NAMESPACES:
            continue
        if not q and AFTER_SCOPE.search(before):
            continue  # ::name, the global namespace: a C library's
        # Counted on from the last name yielded, not from the start of the file each time.
        line += code.count("\n", counted_to, m.start())
        counted_to = m.start()
        yield name, line


def tree_files():
    files = sorted(p for f in FOLDERS for p in (ROOT / f).rglob("*") if p.suffix in (".h", ".cpp", ".hpp"))
    return [p for p in files if "/fuzz/corpus/" not in str(p)]


def analyse(text):
    """The names each header owns and what every file reaches: {file: text} in, a checker out."""
    files = sorted(text)
    code = {p: strip_code(t) for p, t in text.items()}
    includes = {p: [q for q in (resolve_include(n, p) for n in INCLUDE.findall(t)) if q] for p, t in text.items()}

    owner = defaultdict(set)  # name -> headers defining it at namespace scope
    provides = defaultdict(set)  # name -> headers declaring it (a forward declaration too)
    everywhere = defaultdict(int)  # name -> files declaring it at any scope
    per_file_any = {}
    namespace_names = set()
    for p in files:
        per_file_any[p] = names_anywhere(code[p]) | macros(text[p])
        namespace_names |= namespaces(code[p])
        for n in per_file_any[p]:
            everywhere[n] += 1
        if p.suffix != ".cpp":
            forward = forward_declared(code[p])
            for n in declared_names(code[p], namespace_only=True) | macros(text[p]):
                provides[n].add(p)
                if n not in forward:
                    owner[n].add(p)
            for n in forward:
                provides[n].add(p)
    for n in namespace_names:
        owner.pop(n, None)
    closure_cache = {}

    def closure(p):
        if p in closure_cache:
            return closure_cache[p]
        seen, todo = set(), [p]
        while todo:
            q = todo.pop()
            for r in includes.get(q, []):
                if r not in seen:
                    seen.add(r)
                    todo.append(r)
        closure_cache[p] = seen
        return seen

    def findings(p, text_of_p=None):
        """What file p (or p with other text, same declarations) uses without its header."""
        c = code[p] if text_of_p is None else strip_code(text_of_p)
        incs = includes[p] if text_of_p is None else \
            [q for q in (resolve_include(n, p) for n in INCLUDE.findall(text_of_p)) if q]
        reach = {p} | set(incs)
        for q in incs:
            reach |= closure(q)
        known = set(per_file_any[p])
        for q in reach:
            known |= per_file_any.get(q, set())
        out, reported = [], set()
        for name, line in used_names(c, lambda n: n in owner and n not in known and n not in reported):
            reported.add(name)
            where = " or ".join(str(h.relative_to(ROOT)) for h in sorted(owner[name]))
            out.append(f"{p.relative_to(ROOT)}:{line}: uses {name} from {where} without including it")
        return out

    return findings, len(owner), code, closure


# The standard library's names and the header that declares each (any one of several will do).
STD_HEADERS = {
    "optional": "optional", "nullopt": "optional", "variant": "variant", "visit": "variant",
    "holds_alternative": "variant", "get_if": "variant", "monostate": "variant", "any": "any",
    "map": "map", "multimap": "map", "set": "set", "multiset": "set", "unordered_map": "unordered_map",
    "unordered_set": "unordered_set", "deque": "deque", "list": "list", "queue": "queue",
    "priority_queue": "queue", "stack": "stack", "span": "span", "bitset": "bitset", "vector": "vector",
    "array": "array", "string": "string", "to_string": "string", "stod": "string", "stoi": "string",
    "stol": "string", "stoll": "string", "getline": "string istream", "string_view": "string_view",
    "mutex": "mutex", "lock_guard": "mutex", "unique_lock": "mutex", "scoped_lock": "mutex",
    "recursive_mutex": "mutex", "shared_mutex": "shared_mutex", "shared_lock": "shared_mutex",
    "condition_variable": "condition_variable", "condition_variable_any": "condition_variable",
    "thread": "thread", "jthread": "thread", "this_thread": "thread", "stop_token": "stop_token",
    "stop_source": "stop_token", "stop_callback": "stop_token", "atomic": "atomic",
    "atomic_flag": "atomic", "memory_order_relaxed": "atomic", "future": "future", "promise": "future",
    "async": "future", "chrono": "chrono", "ostringstream": "sstream", "istringstream": "sstream",
    "stringstream": "sstream", "ifstream": "fstream", "ofstream": "fstream", "fstream": "fstream",
    "cout": "iostream", "cerr": "iostream", "clog": "iostream", "cin": "iostream", "ostream": "ostream",
    "istream": "istream", "endl": "ostream", "setw": "iomanip", "setprecision": "iomanip",
    "fixed": "ios", "numeric_limits": "limits", "pair": "utility", "make_pair": "utility",
    "move": "utility", "forward": "utility", "swap": "utility", "exchange": "utility",
    "tuple": "tuple", "tie": "tuple", "make_tuple": "tuple", "apply": "tuple",
    "function": "functional", "bind_front": "functional", "hash": "functional",
    "unique_ptr": "memory", "shared_ptr": "memory", "weak_ptr": "memory", "make_unique": "memory",
    "make_shared": "memory", "filesystem": "filesystem", "regex": "regex", "regex_match": "regex",
    "regex_search": "regex", "smatch": "regex", "accumulate": "numeric", "iota": "numeric",
    "inner_product": "numeric", "partial_sum": "numeric", "gcd": "numeric", "lcm": "numeric",
    "midpoint": "numeric", "reduce": "numeric", "numbers": "numbers", "mt19937": "random",
    "mt19937_64": "random", "uniform_real_distribution": "random", "uniform_int_distribution": "random",
    "normal_distribution": "random", "random_device": "random", "runtime_error": "stdexcept",
    "invalid_argument": "stdexcept", "out_of_range": "stdexcept", "logic_error": "stdexcept",
    "exception": "exception", "exception_ptr": "exception", "current_exception": "exception",
    "rethrow_exception": "exception", "initializer_list": "initializer_list",
    "int8_t": "cstdint", "int16_t": "cstdint", "int32_t": "cstdint", "int64_t": "cstdint",
    "uint8_t": "cstdint", "uint16_t": "cstdint", "uint32_t": "cstdint", "uint64_t": "cstdint",
    "size_t": "cstddef", "ptrdiff_t": "cstddef", "byte": "cstddef", "nullptr_t": "cstddef",
    "snprintf": "cstdio", "fopen": "cstdio", "fclose": "cstdio", "FILE": "cstdio", "printf": "cstdio",
    "memcpy": "cstring", "memset": "cstring", "memcmp": "cstring", "strlen": "cstring",
    "strerror": "cstring", "getenv": "cstdlib", "abs": "cstdlib cmath", "exit": "cstdlib",
    "abort": "cstdlib", "strtod": "cstdlib", "sqrt": "cmath", "isfinite": "cmath", "isnan": "cmath",
    "floor": "cmath", "ceil": "cmath", "round": "cmath", "lround": "cmath", "pow": "cmath",
    "hypot": "cmath", "atan2": "cmath", "fabs": "cmath", "sort": "algorithm", "stable_sort": "algorithm",
    "min": "algorithm", "max": "algorithm", "clamp": "algorithm", "find": "algorithm",
    "find_if": "algorithm", "count_if": "algorithm", "any_of": "algorithm", "all_of": "algorithm",
    "none_of": "algorithm", "min_element": "algorithm", "max_element": "algorithm",
    "minmax_element": "algorithm", "nth_element": "algorithm", "lower_bound": "algorithm",
    "upper_bound": "algorithm", "fill": "algorithm", "fill_n": "algorithm", "copy": "algorithm",
    "copy_n": "algorithm", "transform": "algorithm", "reverse": "algorithm", "unique": "algorithm",
    "remove_if": "algorithm", "equal": "algorithm", "ranges": "algorithm ranges",
    "from_chars": "charconv", "to_chars": "charconv", "chars_format": "charconv",
    "source_location": "source_location", "type_index": "typeindex", "back_inserter": "iterator",
    "istreambuf_iterator": "iterator", "distance": "iterator", "next": "iterator", "prev": "iterator",
    "begin": "iterator", "end": "iterator", "size": "iterator", "data": "iterator", "ssize": "iterator",
    "is_same_v": "type_traits", "enable_if_t": "type_traits", "decay_t": "type_traits",
    "underlying_type_t": "type_traits", "is_arithmetic_v": "type_traits", "bit_cast": "bit",
    "countr_zero": "bit", "popcount": "bit", "complex": "complex", "valarray": "valarray",
    "locale": "locale", "setlocale": "clocale", "time_t": "ctime", "gmtime": "ctime", "tm": "ctime",
    "strftime": "ctime", "put_time": "iomanip", "quoted": "iomanip", "errc": "system_error",
    "error_code": "system_error", "system_error": "system_error", "generic_category": "system_error",
    "latch": "latch", "barrier": "barrier", "counting_semaphore": "semaphore",
    "binary_semaphore": "semaphore", "format": "format", "ratio": "ratio", "reference_wrapper": "functional",
    "ref": "functional", "cref": "functional", "invoke": "functional", "not_fn": "functional",
    "less": "functional", "greater": "functional", "plus": "functional", "identity": "functional",
}
STD_USE = re.compile(r"\bstd\s*::\s*([A-Za-z_]\w*)")


def system_include_dirs():
    """The compiler's own search list, plus the third-party folders the build adds (-isystem)."""
    try:
        out = subprocess.run(["c++", "-xc++", "-E", "-v", "-"], input="", capture_output=True, text=True).stderr
    except OSError:
        return []
    dirs, inside = [], False
    for line in out.splitlines():
        if line.startswith("#include <...> search starts here"):
            inside = True
        elif line.startswith("End of search list"):
            break
        elif inside:
            dirs.append(Path(line.strip()))
    return dirs + [Path("/usr/include/eigen3"), Path("/usr/include/imgui")]


def std_findings(files, text, code, closure):
    """Uses of std::name whose header is not among the headers a file reaches."""
    dirs = system_include_dirs()
    if not dirs:
        return []
    sys_cache = {}

    def angled(t):
        return re.findall(r'^\s*#\s*include\s*<([^>]+)>', t, re.MULTILINE)

    resolved = {}  # (name, including folder) -> path or None
    direct = {}  # path -> the paths it includes

    def resolve(n, folder):
        key = (n, folder)
        if key not in resolved:
            cands = ([folder + "/" + n] if folder else []) + [str(d) + "/" + n for d in dirs]
            resolved[key] = next((os.path.normpath(c) for c in cands if os.path.isfile(c)), None)
        return resolved[key]

    def includes_of(path):
        if path not in direct:
            try:
                with open(path, errors="replace") as f:
                    t = f.read()
            except OSError:
                t = ""
            folder = os.path.dirname(path)
            names = angled(t) + re.findall(r'^\s*#\s*include\s*"([^"]+)"', t, re.MULTILINE)
            direct[path] = [r for r in (resolve(n, folder) for n in names) if r]
        return direct[path]

    prefixes = [str(d) + "/" for d in dirs]

    def sys_closure(name):
        """The standard and third-party headers that `#include <name>` brings, itself included."""
        if name in sys_cache:
            return sys_cache[name]
        top = resolve(name, None)
        seen, todo = set(), [top] if top else []
        while todo:
            path = todo.pop()
            if path in seen:
                continue
            seen.add(path)
            todo += includes_of(path)
        names = {p[len(pre):] for p in seen for pre in prefixes if p.startswith(pre)}
        sys_cache[name] = names
        return names

    file_sys_cache = {}

    def file_sys(q):
        """The system headers file q's own angled includes bring."""
        if q not in file_sys_cache:
            have = set()
            for n in angled(text.get(q, "")):
                have |= sys_closure(n)
            file_sys_cache[q] = have
        return file_sys_cache[q]

    out = []
    for p in files:
        used = {}
        for m in STD_USE.finditer(code[p]):
            used.setdefault(m.group(1), code[p].count("\n", 0, m.start()) + 1)
        wanted = {n: STD_HEADERS[n] for n in used if n in STD_HEADERS}
        if not wanted:
            continue
        have = set()
        for q in {p} | closure(p):
            have |= file_sys(q)
        for name, headers in sorted(wanted.items(), key=lambda kv: used[kv[0]]):
            if not any(h in have for h in headers.split()):
                out.append(f"{p.relative_to(ROOT)}:{used[name]}: uses std::{name} without including "
                           f"<{headers.split()[0]}>")
    return out


def main():
    files = tree_files()
    text = {p: p.read_text(errors="replace") for p in files}
    findings_of, owned, code, closure = analyse(text)
    wanted = [Path(a).resolve() for a in sys.argv[1:]] or files
    findings = [f for p in wanted if p in set(files) for f in findings_of(p)]
    findings += std_findings([p for p in wanted if p in set(files)], text, code, closure)
    for f in findings:
        print(f)
    if findings:
        print(f"check_includes: {len(findings)} use(s) of our own names without their header "
              "(add the #include; the unity build hides it until a batch changes)")
        return 1
    print(f"check_includes: {len(files)} files include the header of every one of our names they use "
          f"({owned} names checked)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
