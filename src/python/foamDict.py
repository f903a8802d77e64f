"""Read OpenFOAM dictionaries, and change one entry's value in place, with
the standard library only.

Editing keeps the file as it is (comments, #include lines, $variables,
layout) and replaces only the text of the value: OpenFOAM's foamDictionary
-set rewrites the whole file and expands its #include directives, which
would cut a case's files off from its parameter file.

    d = foamDict.parse(text)            # Dict: key -> value
    d["DEM"]["timeStep"]                # 1e-10 (int, float, str, list, Dict)
    text = foamDict.set_entry(text, "DEM/timeStep", "2e-10")

Values: a number, a word or string (str), a list '( ... )' (Python list),
a sub-dictionary (Dict), or, for an entry of several tokens such as
'uniform (0 0 0)', a Python tuple of them.  Directives (#include ...) are
kept in the text but not followed."""
import re

_NUMBER = re.compile(r"^[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?$")
_DELIMITERS = "{}()[];"


class DictError(Exception):
    """A dictionary that cannot be read or an entry that cannot be set"""


class Dict(dict):
    """A dictionary that remembers where each entry's value is in the text:
    spans[key] = (start, end) character positions"""

    def __init__(self):
        super().__init__()
        self.spans = {}


def _tokens(text):
    """(kind, text, start, end): kind 'word', 'string', 'directive' or a
    delimiter character"""
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c.isspace():
            i += 1
        elif text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j + 1
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            if j < 0:
                raise DictError("unterminated comment at character %d" % i)
            i = j + 2
        elif text.startswith("#{", i):    # a code block, verbatim
            j = text.find("#}", i + 2)
            if j < 0:
                raise DictError("unterminated #{ at character %d" % i)
            yield ("word", text[i:j + 2], i, j + 2)
            i = j + 2
        elif c == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == "\\" else 1
            if j >= n:
                raise DictError("unterminated string at character %d" % i)
            yield ("string", text[i + 1:j], i, j + 1)
            i = j + 1
        elif c in _DELIMITERS:
            yield (c, c, i, i + 1)
            i += 1
        else:
            j = i
            while j < n and not text[j].isspace() and text[j] not in _DELIMITERS \
                    and text[j] != '"' and not text.startswith("//", j) \
                    and not text.startswith("/*", j):
                j += 1
            word = text[i:j]
            k = j
            while k < n and text[k] in " \t":
                k += 1
            if word.startswith("#") and k < n and text[k] == "{":
                # '#eval{ ... }' and the like: one value, verbatim
                depth, j = 0, k
                while j < n:
                    depth += {"{": 1, "}": -1}.get(text[j], 0)
                    j += 1
                    if depth == 0:
                        break
                yield ("word", text[i:j], i, j)
            else:
                yield ("directive" if word.startswith("#") else "word", word, i, j)
            i = j


def _scalar(kind, word):
    if kind == "word" and _NUMBER.match(word):
        value = float(word)
        if re.match(r"^[-+]?\d+$", word):
            value = int(word)
        return value
    return word


class _Parser:
    def __init__(self, text):
        self.toks = list(_tokens(text))
        self.i = 0

    def peek(self):
        return self.toks[self.i] if self.i < len(self.toks) else None

    def next(self):
        tok = self.peek()
        if tok is None:
            raise DictError("unexpected end of the dictionary")
        self.i += 1
        return tok

    def dictionary(self, closing):
        d = Dict()
        while True:
            tok = self.peek()
            if tok is None:
                if closing:
                    raise DictError("missing '}' at the end")
                return d
            if tok[0] == "}":
                if not closing:
                    raise DictError("unexpected '}' at character %d" % tok[2])
                self.i += 1
                return d
            if tok[0] == "directive":
                self.i += 1
                # '#include "file"' and the like take one argument
                if self.peek() is not None and self.peek()[0] == "string":
                    self.i += 1
                continue
            if tok[0] not in ("word", "string"):
                raise DictError("expected a keyword at character %d, found '%s'"
                                % (tok[2], tok[1]))
            self.i += 1
            key = tok[1]
            if self.peek() is not None and self.peek()[0] == "{":
                start = self.next()[2]
                d[key] = self.dictionary(True)
                d.spans[key] = (start, self.toks[self.i - 1][3])
                continue
            values, start, end = [], None, None
            while True:
                t = self.peek()
                if t is None:
                    raise DictError("entry '%s' has no ';'" % key)
                if t[0] == ";":
                    self.i += 1
                    break
                if t[0] in "})]":
                    raise DictError("entry '%s': unexpected '%s' at character %d"
                                    % (key, t[1], t[2]))
                v, s, e = self.value()
                values.append(v)
                start = s if start is None else start
                end = e
            d[key] = values[0] if len(values) == 1 else tuple(values)
            d.spans[key] = (start, end)

    def value(self):
        """One value: (python value, start, end)"""
        tok = self.next()
        if tok[0] == "(":
            items = []
            while self.peek() is not None and self.peek()[0] != ")":
                items.append(self.value()[0])
            return items, tok[2], self.next()[3]
        if tok[0] == "[":               # dimensions: kept as text
            while self.next()[0] != "]":
                pass
            return "[...]", tok[2], self.toks[self.i - 1][3]
        if tok[0] == "{":
            d = self.dictionary(True)
            return d, tok[2], self.toks[self.i - 1][3]
        if tok[0] in ("word", "string", "directive"):
            return _scalar(tok[0], tok[1]), tok[2], tok[3]
        raise DictError("unexpected '%s' at character %d" % (tok[1], tok[2]))


def parse(text):
    """The dictionary in text (FoamFile header included as an entry)"""
    return _Parser(text).dictionary(False)


def read(path):
    try:
        with open(path) as f:
            return parse(f.read())
    except OSError as e:
        raise DictError("cannot read %s: %s" % (path, e.strerror))
    except DictError as e:
        raise DictError("%s: %s" % (path, e))


def lookup(d, path):
    """The value at a '/'-separated path, or KeyError naming the path"""
    node = d
    for part in path.split("/"):
        if not isinstance(node, dict) or part not in node:
            raise KeyError(path)
        node = node[part]
    return node


def set_entry(text, path, value):
    """text with the value of the entry at path replaced by the string
    value.  The entry must be written literally in this text (not come
    from an #include or a $variable)."""
    d = parse(text)
    parts = path.split("/")
    offset_dict = d
    for part in parts[:-1]:
        if not isinstance(offset_dict.get(part), Dict):
            raise DictError("no sub-dictionary '%s' (entry %s)" % (part, path))
        offset_dict = offset_dict[part]
    key = parts[-1]
    if key not in offset_dict or isinstance(offset_dict[key], Dict):
        raise DictError("no entry '%s'" % path)
    old = offset_dict[key]
    if isinstance(old, str) and old.startswith("$"):
        raise DictError("entry '%s' is %s, a variable: set it where it is "
                        "defined" % (path, old))
    start, end = offset_dict.spans[key]
    return text[:start] + value + text[end:]
