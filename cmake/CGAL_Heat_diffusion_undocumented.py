#!/usr/bin/env python3
"""Lists the public classes and members of the reference that have no documentation.

Reads the XML of a Doxygen run with EXTRACT_ALL = YES (every entity, documented or
not; `\\cond` sections and the excluded internal namespaces stay out) and prints one
warning per public class, function, variable, type or enumerator declared in a header
under INCLUDE_DIR whose brief and detailed descriptions are both empty. Doxygen itself
does not warn about them: with HIDE_UNDOC_MEMBERS it drops them silently (a comment
attached to the wrong declaration leaves a constructor out of the reference).
Exit status 1 if there is one.

Usage: CGAL_Heat_diffusion_undocumented.py XML_DIR INCLUDE_DIR
"""
import glob
import os
import sys
import xml.etree.ElementTree as ET


def described(element):
    for tag in ("briefdescription", "detaileddescription"):
        node = element.find(tag)
        if node is not None and "".join(node.itertext()).strip():
            return True
    return False


def location(element):
    node = element.find("location")
    if node is None:
        return "", 0
    return node.get("file", ""), int(node.get("line", "0"))


def main():
    xml_dir, include_dir = sys.argv[1], os.path.realpath(sys.argv[2])
    problems = []

    def in_headers(path):
        # Doxygen writes the paths relative to STRIP_FROM_PATH (the include folder)
        full = os.path.realpath(os.path.join(include_dir, path))
        return os.path.isfile(full) and full.startswith(include_dir + os.sep)

    compounds = []
    for path in sorted(glob.glob(os.path.join(xml_dir, "*.xml"))):
        compounds += ET.parse(path).getroot().findall("compounddef")
    # A class nested in a private class is not part of the API, whatever its own access.
    access = {c.findtext("compoundname", ""): c.get("prot", "public")
              for c in compounds if c.get("kind") in ("class", "struct", "union")}

    def public(name):
        while name:
            if access.get(name, "public") != "public":
                return False
            name = name.rpartition("::")[0]
        return True

    for compound in compounds:
        kind = compound.get("kind")
        name = compound.findtext("compoundname", "")
        if kind in ("class", "struct", "union"):
            if not public(name):
                continue
            file, line = location(compound)
            if in_headers(file) and not described(compound):
                problems.append((file, line, "%s %s is not documented" % (kind, name)))
        elif kind not in ("namespace", "file"):
            continue  # groups and pages repeat the members of namespaces and files
        for section in compound.findall("sectiondef"):
            for member in section.findall("memberdef"):
                if member.get("prot", "public") != "public":
                    continue
                file, line = location(member)
                if not in_headers(file):
                    continue
                member_name = name + "::" + member.findtext("name", "")
                if not described(member):
                    problems.append((file, line, "%s %s is not documented" % (member.get("kind"), member_name)))
                for value in member.findall("enumvalue"):
                    if not described(value):
                        problems.append((file, line, "enumerator %s::%s is not documented"
                                         % (member_name, value.findtext("name", ""))))
    for file, line, text in sorted(set(problems)):
        print("%s:%d: warning: %s (the reference would not show it)" % (file, line, text))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
