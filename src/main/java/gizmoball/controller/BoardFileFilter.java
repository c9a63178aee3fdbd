package gizmoball.controller;

import java.io.File;
import java.util.Locale;
import java.util.Set;
import javax.swing.filechooser.FileFilter;

/**
 * The file chooser's "Board files": folders, our .txt and the endings of the boards other implementations write
 * (.gizmo, .gb, .giz, .gzm), and names without an ending, which several of them use.
 */
final class BoardFileFilter extends FileFilter {
    private static final Set<String> ENDINGS = Set.of("txt", "gizmo", "gb", "giz", "gzm");

    @Override
    public boolean accept(File file) {
        return file.isDirectory() || isBoardFileName(file.getName());
    }

    static boolean isBoardFileName(String name) {
        int dot = name.lastIndexOf('.');
        return dot <= 0 || ENDINGS.contains(name.substring(dot + 1).toLowerCase(Locale.ROOT));
    }

    @Override
    public String getDescription() {
        return "Board files (.txt, .gizmo, .gb, .giz, .gzm, no ending)";
    }
}
