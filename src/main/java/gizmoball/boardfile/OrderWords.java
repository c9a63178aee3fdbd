package gizmoball.boardfile;

import gizmoball.model.gizmo.Action;
import gizmoball.model.gizmo.Order;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.stream.Collectors;

/**
 * How a connection's or a key binding's {@link Order} is written after its target, on our {@code #@} form of the
 * line: an action word, then {@code after} and the delay in seconds, each only where the order has it
 * ({@code fire}, {@code after 0.5}, {@code raise after 0.25}).
 */
public final class OrderWords {
    static final String AFTER = "after";

    private OrderWords() {
    }

    /** The words after the target, each with a space before it; empty for the default order. */
    public static String of(Order order) {
        return order.action().map(a -> " " + a.word()).orElse("")
                + (order.delay() == 0 ? "" : " " + AFTER + " " + Decimals.format(order.delay()));
    }

    /** Whether the word can begin the words of an order: an action or {@code after}. */
    static boolean startsAnOrder(String word) {
        return word.equalsIgnoreCase(AFTER) || Action.named(word).isPresent();
    }

    /** The order the words after a target say, or why they say none. */
    static Order parse(List<String> words) throws Refusal {
        int i = 0;
        Optional<Action> action = Optional.empty();
        if (i < words.size() && !words.get(i).equalsIgnoreCase(AFTER)) {
            String word = words.get(i++);
            action = Optional.of(Action.named(word).orElseThrow(() -> new Refusal("unknown action '"
                    + word + "': an action is one of " + Arrays.stream(Action.values()).map(Action::word)
                    .collect(Collectors.joining(", ")))));
        }
        double delay = 0;
        if (i < words.size()) {
            if (!words.get(i).equalsIgnoreCase(AFTER) || i + 2 != words.size()) {
                throw new Refusal("after the target come an action, then '" + AFTER
                        + " <seconds>', each only if given; found '" + String.join(" ", words) + "'");
            }
            OptionalDouble seconds = Decimals.parse(words.get(i + 1));
            if (seconds.isEmpty()) {
                throw new Refusal("delay '" + words.get(i + 1) + "' is not a number of seconds");
            }
            delay = seconds.getAsDouble();
        }
        return new Order(action, delay);
    }
}
