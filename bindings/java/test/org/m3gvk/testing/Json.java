package org.m3gvk.testing;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A minimal JSON reader for the tests (the corpus manifest): objects become
 * LinkedHashMap, arrays ArrayList, numbers Double, plus String, Boolean and
 * null. Throws IllegalArgumentException at the offset of a syntax error.
 */
public final class Json {
    private final String s;
    private int i;

    private Json(String s) {
        this.s = s;
    }

    public static Object parse(String text) {
        Json j = new Json(text);
        Object v = j.value();
        j.space();
        if (j.i != text.length()) throw j.error("trailing characters");
        return v;
    }

    private IllegalArgumentException error(String what) {
        return new IllegalArgumentException("JSON: " + what + " at offset " + i);
    }

    private void space() {
        while (i < s.length() && Character.isWhitespace(s.charAt(i))) ++i;
    }

    private Object value() {
        space();
        if (i >= s.length()) throw error("unexpected end");
        char c = s.charAt(i);
        if (c == '{') return object();
        if (c == '[') return array();
        if (c == '"') return string();
        if (s.startsWith("true", i)) {
            i += 4;
            return Boolean.TRUE;
        }
        if (s.startsWith("false", i)) {
            i += 5;
            return Boolean.FALSE;
        }
        if (s.startsWith("null", i)) {
            i += 4;
            return null;
        }
        int start = i;
        while (i < s.length() && "+-0123456789.eE".indexOf(s.charAt(i)) >= 0) ++i;
        if (start == i) throw error("unexpected '" + c + "'");
        return Double.valueOf(s.substring(start, i));
    }

    private Map<String, Object> object() {
        Map<String, Object> out = new LinkedHashMap<>();
        ++i;
        space();
        if (s.charAt(i) == '}') {
            ++i;
            return out;
        }
        while (true) {
            space();
            String key = string();
            space();
            if (s.charAt(i++) != ':') throw error("':' expected");
            out.put(key, value());
            space();
            char c = s.charAt(i++);
            if (c == '}') return out;
            if (c != ',') throw error("',' or '}' expected");
        }
    }

    private List<Object> array() {
        List<Object> out = new ArrayList<>();
        ++i;
        space();
        if (s.charAt(i) == ']') {
            ++i;
            return out;
        }
        while (true) {
            out.add(value());
            space();
            char c = s.charAt(i++);
            if (c == ']') return out;
            if (c != ',') throw error("',' or ']' expected");
        }
    }

    private String string() {
        if (s.charAt(i) != '"') throw error("string expected");
        StringBuilder b = new StringBuilder();
        for (++i; s.charAt(i) != '"'; ++i) {
            char c = s.charAt(i);
            if (c == '\\') {
                char e = s.charAt(++i);
                switch (e) {
                    case 'n': b.append('\n'); break;
                    case 't': b.append('\t'); break;
                    case 'r': b.append('\r'); break;
                    case 'b': b.append('\b'); break;
                    case 'f': b.append('\f'); break;
                    case 'u': b.append((char) Integer.parseInt(s.substring(i + 1, i + 5), 16)); i += 4; break;
                    default: b.append(e);
                }
            } else {
                b.append(c);
            }
        }
        ++i;
        return b.toString();
    }
}
