"""Reads `llvm-objdump -d -C` output; prints, for every `ballcast_*` wrapper, the panic symbols its
code can reach through direct calls and branches (`bl`, `b`, `b<cond>`), with one call path each.
Indirect calls (`blx reg`) are not followed; the link-time check does not depend on this report."""
import re
import sys

PANIC = re.compile(r"panic|begin_unwind|unwrap_failed|expect_failed|_fail\b|slice_(start|end)_index")
head = re.compile(r"^[0-9a-f]+ <(.*)>:$")
jump = re.compile(r"\tb(?:l|eq|ne|cs|hs|cc|lo|mi|pl|vs|vc|hi|ls|ge|lt|gt|le|al)?(?:\.w|\.n)?\t0x[0-9a-f]+ <(.*?)(?:\+0x[0-9a-f]+)?>")

edges, fn = {}, None
for line in sys.stdin:
    m = head.match(line)
    if m:
        fn = m.group(1)
        edges.setdefault(fn, set())
        continue
    m = jump.search(line)
    if m and fn is not None and m.group(1) != fn:
        edges[fn].add(m.group(1))

def short(name):
    """Unescapes a legacy Rust symbol and elides typenum's long generic arguments."""
    for a, b in (("$LT$", "<"), ("$GT$", ">"), ("$u20$", " "), ("$C$", ","), ("..", "::")):
        name = name.replace(a, b)
    name = re.sub(r"::h[0-9a-f]{16}$", "", name).lstrip("_")
    while (i := name.find("<typenum")) >= 0:
        depth, j = 0, i
        while j < len(name):
            depth += {"<": 1, ">": -1}.get(name[j], 0)
            j += 1
            if depth == 0:
                break
        name = name[:i] + "<…>" + name[j:]
    return name

found = False
for root in sorted(f for f in edges if f.startswith("ballcast_")):
    parent, queue = {root: None}, [root]
    while queue:
        f = queue.pop(0)
        for g in sorted(edges.get(f, ())):
            if g not in parent:
                parent[g] = f
                queue.append(g)
    hits = sorted(g for g in parent if PANIC.search(g) and g != root)
    if not hits:
        print(f"  {root}: no panic symbol reachable")
        continue
    found = True
    first = min(hits, key=lambda g: (not g.startswith("core::panicking::panic_const"), g))
    path, g = [], first
    while g is not None:
        path.append(short(g))
        g = parent[g]
    print(f"  {root}: reaches {', '.join(short(h) for h in hits)}")
    print("    path: " + "\n       -> ".join(reversed(path)))
sys.exit(1 if found else 0)
