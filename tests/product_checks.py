"""What the product's structure checks (tests/product_*.py) share: how they report."""
import sys


def self_test_result(name, checks):
    """Prints each (found, expected) pair of checks that differ; 0 when none does, else 1."""
    failed = [(got, want) for got, want in checks if got != want]
    for got, want in failed:
        print(f"{name} self-test: found {got}, expected {want}")
    print(f"{name} self-test: " + ("failed" if failed else f"all {len(checks)} checks pass"))
    return 1 if failed else 0


def report(problems, heading, none):
    """Prints the problems under heading, or none where there are none; the exit status."""
    if problems:
        print(heading)
        print("\n".join(problems))
        return 1
    print(none)
    return 0


def usage(doc):
    """Prints the usage, a check's docstring's first paragraph; the exit status."""
    print(doc.split("\n\n")[0], file=sys.stderr)
    return 2
