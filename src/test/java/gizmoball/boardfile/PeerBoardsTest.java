package gizmoball.boardfile;

import java.nio.file.Path;

/**
 * The boards written by other implementations (../shared/peer-boards, the repository's sibling): the corpus
 * test skips, saying so, in a clone without it; {@link DialectBoardsTest} still covers every tolerated feature.
 */
class PeerBoardsTest extends BoardCorpusTest {
    @Override
    Path folder() {
        return Path.of(System.getProperty("user.dir")).toAbsolutePath().resolveSibling("shared")
                .resolve("peer-boards");
    }

    @Override
    String table() {
        return "/peer-boards-expected.tsv";
    }
}
