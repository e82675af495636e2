

module texture_address(s,t,lambda,second,ws,hs,levels,base,min_linear,mag_linear,mip,wrap_s,wrap_t,lanes,addr0,addr1,addr2,addr3,banks,alpha,beta,two_levels,frac);
    
    // Module arguments
    input wire  [28:0] s;
    input wire  [28:0] t;
    input wire  [31:0] lambda;
    input wire  second;
    input wire  [3:0] ws;
    input wire  [3:0] hs;
    input wire  [3:0] levels;
    input wire  [25:0] base;
    input wire  min_linear;
    input wire  mag_linear;
    input wire  [1:0] mip;
    input wire  [1:0] wrap_s;
    input wire  [1:0] wrap_t;
    output reg  [3:0] lanes;
    output reg  [25:0] addr0;
    output reg  [25:0] addr1;
    output reg  [25:0] addr2;
    output reg  [25:0] addr3;
    output reg  [7:0] banks;
    output reg  [7:0] alpha;
    output reg  [7:0] beta;
    output reg  two_levels;
    output reg  [5:0] frac;
    
    // Constant declarations
    localparam  bank_id$0 = 2'b0;
    localparam  bank_id$1 = 2'b1;
    localparam  bank_id$2 = 2'b10;
    localparam  bank_id$3 = 2'b11;
    localparam  lane_bit$0 = 4'h1;
    localparam  lane_bit$1 = 4'h2;
    localparam  lane_bit$2 = 4'h4;
    localparam  lane_bit$3 = 4'h8;
    localparam  level_id$0 = 26'h0;
    localparam  level_id$1 = 26'h1;
    localparam  level_id$2 = 26'h2;
    localparam  level_id$3 = 26'h3;
    localparam  level_id$4 = 26'h4;
    localparam  level_id$5 = 26'h5;
    localparam  level_id$6 = 26'h6;
    localparam  level_id$7 = 26'h7;
    localparam  level_id$8 = 26'h8;
    localparam  level_id$9 = 26'h9;
    localparam  level_id$10 = 26'ha;
    localparam  level_id$11 = 26'hb;
    localparam  level_id$12 = 26'hc;
    
    // Stub signals
    reg  [28:0] across$coord;
    reg  [3:0] across$size_log2;
    reg  across$linear;
    reg  [1:0] across$wrap;
    wire  [12:0] across$i0;
    wire  [12:0] across$i1;
    wire  [7:0] across$frac;
    reg  [28:0] up$coord;
    reg  [3:0] up$size_log2;
    reg  up$linear;
    reg  [1:0] up$wrap;
    wire  [12:0] up$i0;
    wire  [12:0] up$i1;
    wire  [7:0] up$frac;
    reg  [12:0] word$0$i;
    reg  [12:0] word$0$j;
    reg  [25:0] word$0$first;
    reg  [3:0] word$0$pw;
    reg  [3:0] word$0$ph;
    wire  [1:0] word$0$bank;
    wire  [25:0] word$0$addr;
    reg  [12:0] word$1$i;
    reg  [12:0] word$1$j;
    reg  [25:0] word$1$first;
    reg  [3:0] word$1$pw;
    reg  [3:0] word$1$ph;
    wire  [1:0] word$1$bank;
    wire  [25:0] word$1$addr;
    reg  [12:0] word$2$i;
    reg  [12:0] word$2$j;
    reg  [25:0] word$2$first;
    reg  [3:0] word$2$pw;
    reg  [3:0] word$2$ph;
    wire  [1:0] word$2$bank;
    wire  [25:0] word$2$addr;
    reg  [12:0] word$3$i;
    reg  [12:0] word$3$j;
    reg  [25:0] word$3$first;
    reg  [3:0] word$3$pw;
    reg  [3:0] word$3$ph;
    wire  [1:0] word$3$bank;
    wire  [25:0] word$3$addr;
    
    // Local signals
    reg  magnify;
    reg  [31:0] q;
    reg  [31:0] d;
    reg  [3:0] level;
    reg  [3:0] sw;
    reg  [3:0] sh;
    reg  [3:0] pw;
    reg  [3:0] ph;
    reg  [25:0] offset;
    reg  [25:0] ws_a;
    reg  [25:0] hs_a;
    reg  [25:0] level_a;
    reg  [25:0] pk$0;
    reg  [25:0] pk$1;
    reg  [25:0] pk$2;
    reg  [25:0] pk$3;
    reg  [25:0] pk$4;
    reg  [25:0] pk$5;
    reg  [25:0] pk$6;
    reg  [25:0] pk$7;
    reg  [25:0] pk$8;
    reg  [25:0] pk$9;
    reg  [25:0] pk$10;
    reg  [25:0] pk$11;
    reg  [25:0] pk$12;
    reg  [25:0] addr$0;
    reg  [25:0] addr$1;
    reg  [25:0] addr$2;
    reg  [25:0] addr$3;
    
    // Sub module instances
    texture_address$across across(
        .coord(across$coord),
        .size_log2(across$size_log2),
        .linear(across$linear),
        .wrap(across$wrap),
        .i0(across$i0),
        .i1(across$i1),
        .frac(across$frac)
    );
    texture_address$up up(
        .coord(up$coord),
        .size_log2(up$size_log2),
        .linear(up$linear),
        .wrap(up$wrap),
        .i0(up$i0),
        .i1(up$i1),
        .frac(up$frac)
    );
    texture_address$word$0 word$0(
        .i(word$0$i),
        .j(word$0$j),
        .first(word$0$first),
        .pw(word$0$pw),
        .ph(word$0$ph),
        .bank(word$0$bank),
        .addr(word$0$addr)
    );
    texture_address$word$1 word$1(
        .i(word$1$i),
        .j(word$1$j),
        .first(word$1$first),
        .pw(word$1$pw),
        .ph(word$1$ph),
        .bank(word$1$bank),
        .addr(word$1$addr)
    );
    texture_address$word$2 word$2(
        .i(word$2$i),
        .j(word$2$j),
        .first(word$2$first),
        .pw(word$2$pw),
        .ph(word$2$ph),
        .bank(word$2$bank),
        .addr(word$2$addr)
    );
    texture_address$word$3 word$3(
        .i(word$3$i),
        .j(word$3$j),
        .first(word$3$first),
        .pw(word$3$pw),
        .ph(word$3$ph),
        .bank(word$3$bank),
        .addr(word$3$addr)
    );
    
    // Update code
    always @(*) begin
        q = ((levels) & 32'hffffffff) - 32'h1;
        magnify = lambda[32'h1f] | ~|lambda;
        two_levels = 1'b0;
        frac = 32'h0;
        d = 32'h0;
        if (~magnify) begin
            if (mip == 32'h1) begin
                d = (lambda + 32'h1f) >> 32'h6;
                if (d > q) begin
                    d = q;
                end
            end
            if (mip == 32'h2) begin
                d = lambda >> 32'h6;
                if (d >= q) begin
                    d = q;
                end
                else begin
                    two_levels = 1'b1;
                    frac = lambda[(32'h0)+:(6)];
                    if (second) begin
                        d = d + 32'h1;
                    end
                end
            end
        end
        level = d[(32'h0)+:(4)];
        sw = 32'h0;
        if (ws > level) begin
            sw = ws - level;
        end
        sh = 32'h0;
        if (hs > level) begin
            sh = hs - level;
        end
        pw = 32'h0;
        if (|sw) begin
            pw = sw - 32'h1;
        end
        ph = 32'h0;
        if (|sh) begin
            ph = sh - 32'h1;
        end
        ws_a = ((ws) & 26'h3ffffff);
        hs_a = ((hs) & 26'h3ffffff);
        level_a = ((level) & 26'h3ffffff);
        offset = base;
        pk$0 = 32'h2;
        if (ws_a > level_id$0 + 32'h1) begin
            pk$0 = pk$0 + ws_a - level_id$0 - 32'h1;
        end
        if (hs_a > level_id$0 + 32'h1) begin
            pk$0 = pk$0 + hs_a - level_id$0 - 32'h1;
        end
        if (level_id$0 < level_a) begin
            offset = offset + (((32'h1) & 26'h3ffffff) << pk$0);
        end
        pk$1 = 32'h2;
        if (ws_a > level_id$1 + 32'h1) begin
            pk$1 = pk$1 + ws_a - level_id$1 - 32'h1;
        end
        if (hs_a > level_id$1 + 32'h1) begin
            pk$1 = pk$1 + hs_a - level_id$1 - 32'h1;
        end
        if (level_id$1 < level_a) begin
            offset = offset + (((32'h1) & 26'h3ffffff) << pk$1);
        end
        pk$2 = 32'h2;
        if (ws_a > level_id$2 + 32'h1) begin
            pk$2 = pk$2 + ws_a - level_id$2 - 32'h1;
        end
        if (hs_a > level_id$2 + 32'h1) begin
            pk$2 = pk$2 + hs_a - level_id$2 - 32'h1;
        end
        if (level_id$2 < level_a) begin
            offset = offset + (((32'h1) & 26'h3ffffff) << pk$2);
        end
        pk$3 = 32'h2;
        if (ws_a > level_id$3 + 32'h1) begin
            pk$3 = pk$3 + ws_a - level_id$3 - 32'h1;
        end
        if (hs_a > level_id$3 + 32'h1) begin
            pk$3 = pk$3 + hs_a - level_id$3 - 32'h1;
        end
        if (level_id$3 < level_a) begin
            offset = offset + (((32'h1) & 26'h3ffffff) << pk$3);
        end
        pk$4 = 32'h2;
        if (ws_a > level_id$4 + 32'h1) begin
            pk$4 = pk$4 + ws_a - level_id$4 - 32'h1;
        end
        if (hs_a > level_id$4 + 32'h1) begin
            pk$4 = pk$4 + hs_a - level_id$4 - 32'h1;
        end
        if (level_id$4 < level_a) begin
            offset = offset + (((32'h1) & 26'h3ffffff) << pk$4);
        end
        pk$5 = 32'h2;
        if (ws_a > level_id$5 + 32'h1) begin
            pk$5 = pk$5 + ws_a - level_id$5 - 32'h1;
        end
        if (hs_a > level_id$5 + 32'h1) begin
            pk$5 = pk$5 + hs_a - level_id$5 - 32'h1;
        end
        if (level_id$5 < level_a) begin
            offset = offset + (((32'h1) & 26'h3ffffff) << pk$5);
        end
        pk$6 = 32'h2;
        if (ws_a > level_id$6 + 32'h1) begin
            pk$6 = pk$6 + ws_a - level_id$6 - 32'h1;
        end
        if (hs_a > level_id$6 + 32'h1) begin
            pk$6 = pk$6 + hs_a - level_id$6 - 32'h1;
        end
        if (level_id$6 < level_a) begin
            offset = offset + (((32'h1) & 26'h3ffffff) << pk$6);
        end
        pk$7 = 32'h2;
        if (ws_a > level_id$7 + 32'h1) begin
            pk$7 = pk$7 + ws_a - level_id$7 - 32'h1;
        end
        if (hs_a > level_id$7 + 32'h1) begin
            pk$7 = pk$7 + hs_a - level_id$7 - 32'h1;
        end
        if (level_id$7 < level_a) begin
            offset = offset + (((32'h1) & 26'h3ffffff) << pk$7);
        end
        pk$8 = 32'h2;
        if (ws_a > level_id$8 + 32'h1) begin
            pk$8 = pk$8 + ws_a - level_id$8 - 32'h1;
        end
        if (hs_a > level_id$8 + 32'h1) begin
            pk$8 = pk$8 + hs_a - level_id$8 - 32'h1;
        end
        if (level_id$8 < level_a) begin
            offset = offset + (((32'h1) & 26'h3ffffff) << pk$8);
        end
        pk$9 = 32'h2;
        if (ws_a > level_id$9 + 32'h1) begin
            pk$9 = pk$9 + ws_a - level_id$9 - 32'h1;
        end
        if (hs_a > level_id$9 + 32'h1) begin
            pk$9 = pk$9 + hs_a - level_id$9 - 32'h1;
        end
        if (level_id$9 < level_a) begin
            offset = offset + (((32'h1) & 26'h3ffffff) << pk$9);
        end
        pk$10 = 32'h2;
        if (ws_a > level_id$10 + 32'h1) begin
            pk$10 = pk$10 + ws_a - level_id$10 - 32'h1;
        end
        if (hs_a > level_id$10 + 32'h1) begin
            pk$10 = pk$10 + hs_a - level_id$10 - 32'h1;
        end
        if (level_id$10 < level_a) begin
            offset = offset + (((32'h1) & 26'h3ffffff) << pk$10);
        end
        pk$11 = 32'h2;
        if (ws_a > level_id$11 + 32'h1) begin
            pk$11 = pk$11 + ws_a - level_id$11 - 32'h1;
        end
        if (hs_a > level_id$11 + 32'h1) begin
            pk$11 = pk$11 + hs_a - level_id$11 - 32'h1;
        end
        if (level_id$11 < level_a) begin
            offset = offset + (((32'h1) & 26'h3ffffff) << pk$11);
        end
        pk$12 = 32'h2;
        if (ws_a > level_id$12 + 32'h1) begin
            pk$12 = pk$12 + ws_a - level_id$12 - 32'h1;
        end
        if (hs_a > level_id$12 + 32'h1) begin
            pk$12 = pk$12 + hs_a - level_id$12 - 32'h1;
        end
        if (level_id$12 < level_a) begin
            offset = offset + (((32'h1) & 26'h3ffffff) << pk$12);
        end
        across$coord = s;
        across$size_log2 = sw;
        across$wrap = wrap_s;
        up$coord = t;
        up$size_log2 = sh;
        up$wrap = wrap_t;
        across$linear = min_linear;
        up$linear = min_linear;
        if (magnify) begin
            across$linear = mag_linear;
            up$linear = mag_linear;
        end
        alpha = across$frac;
        beta = up$frac;
        word$0$i = across$i0;
        word$1$i = across$i1;
        word$2$i = across$i0;
        word$3$i = across$i1;
        word$0$j = up$i0;
        word$1$j = up$i0;
        word$2$j = up$i1;
        word$3$j = up$i1;
        word$0$first = offset;
        word$0$pw = pw;
        word$0$ph = ph;
        word$1$first = offset;
        word$1$pw = pw;
        word$1$ph = ph;
        word$2$first = offset;
        word$2$pw = pw;
        word$2$ph = ph;
        word$3$first = offset;
        word$3$pw = pw;
        word$3$ph = ph;
        banks = ((word$0$bank) & 8'hff) | (((word$1$bank) & 8'hff) << 32'h2) | (((word$2$bank) & 8'hff) << 32'h4) | (((word$3$bank) & 8'hff) << 32'h6);
        lanes = 32'h0;
        addr$0 = 32'h0;
        if (word$0$bank == bank_id$0) begin
            addr$0 = word$0$addr;
            lanes = lanes | lane_bit$0;
        end
        if (word$1$bank == bank_id$0) begin
            addr$0 = word$1$addr;
            lanes = lanes | lane_bit$0;
        end
        if (word$2$bank == bank_id$0) begin
            addr$0 = word$2$addr;
            lanes = lanes | lane_bit$0;
        end
        if (word$3$bank == bank_id$0) begin
            addr$0 = word$3$addr;
            lanes = lanes | lane_bit$0;
        end
        addr$1 = 32'h0;
        if (word$0$bank == bank_id$1) begin
            addr$1 = word$0$addr;
            lanes = lanes | lane_bit$1;
        end
        if (word$1$bank == bank_id$1) begin
            addr$1 = word$1$addr;
            lanes = lanes | lane_bit$1;
        end
        if (word$2$bank == bank_id$1) begin
            addr$1 = word$2$addr;
            lanes = lanes | lane_bit$1;
        end
        if (word$3$bank == bank_id$1) begin
            addr$1 = word$3$addr;
            lanes = lanes | lane_bit$1;
        end
        addr$2 = 32'h0;
        if (word$0$bank == bank_id$2) begin
            addr$2 = word$0$addr;
            lanes = lanes | lane_bit$2;
        end
        if (word$1$bank == bank_id$2) begin
            addr$2 = word$1$addr;
            lanes = lanes | lane_bit$2;
        end
        if (word$2$bank == bank_id$2) begin
            addr$2 = word$2$addr;
            lanes = lanes | lane_bit$2;
        end
        if (word$3$bank == bank_id$2) begin
            addr$2 = word$3$addr;
            lanes = lanes | lane_bit$2;
        end
        addr$3 = 32'h0;
        if (word$0$bank == bank_id$3) begin
            addr$3 = word$0$addr;
            lanes = lanes | lane_bit$3;
        end
        if (word$1$bank == bank_id$3) begin
            addr$3 = word$1$addr;
            lanes = lanes | lane_bit$3;
        end
        if (word$2$bank == bank_id$3) begin
            addr$3 = word$2$addr;
            lanes = lanes | lane_bit$3;
        end
        if (word$3$bank == bank_id$3) begin
            addr$3 = word$3$addr;
            lanes = lanes | lane_bit$3;
        end
        addr0 = addr$0;
        addr1 = addr$1;
        addr2 = addr$2;
        addr3 = addr$3;
    end
    
endmodule // texture_address


module texture_address$across(coord,size_log2,linear,wrap,i0,i1,frac);
    
    // Module arguments
    input wire  [28:0] coord;
    input wire  [3:0] size_log2;
    input wire  linear;
    input wire  [1:0] wrap;
    output reg  [12:0] i0;
    output reg  [12:0] i1;
    output reg  [7:0] frac;
    
    // Stub signals
    reg  [21:0] wrap0$i;
    reg  [3:0] wrap0$size_log2;
    reg  [1:0] wrap0$mode;
    wire  [12:0] wrap0$wrapped;
    reg  [21:0] wrap1$i;
    reg  [3:0] wrap1$size_log2;
    reg  [1:0] wrap1$mode;
    wire  [12:0] wrap1$wrapped;
    
    // Local signals
    reg  [29:0] wide;
    reg  [29:0] u;
    reg  [21:0] first;
    reg  [21:0] second;
    
    // Sub module instances
    texture_address$across$wrap0 wrap0(
        .i(wrap0$i),
        .size_log2(wrap0$size_log2),
        .mode(wrap0$mode),
        .wrapped(wrap0$wrapped)
    );
    texture_address$across$wrap1 wrap1(
        .i(wrap1$i),
        .size_log2(wrap1$size_log2),
        .mode(wrap1$mode),
        .wrapped(wrap1$wrapped)
    );
    
    // Update code
    always @(*) begin
        wide = ((coord) & 30'h3fffffff);
        if (coord[32'h1c]) begin
            wide = ((coord) & 30'h3fffffff) | ((32'h20000000) & 30'h3fffffff);
        end
        u = wide >> (((32'hc) & 30'h3fffffff) - ((size_log2) & 30'h3fffffff));
        if (coord[32'h1c]) begin
            u = (wide >> (((32'hc) & 30'h3fffffff) - ((size_log2) & 30'h3fffffff))) | ~(((32'h3fffffff) & 30'h3fffffff) >> (((32'hc) & 30'h3fffffff) - ((size_log2) & 30'h3fffffff)));
        end
        if (linear) begin
            u = u - ((32'h80) & 30'h3fffffff);
        end
        first = u[(32'h8)+:(22)];
        second = first;
        frac = 32'h0;
        if (linear) begin
            second = first + 32'h1;
            frac = u[(32'h0)+:(8)];
        end
        wrap0$i = first;
        wrap0$size_log2 = size_log2;
        wrap0$mode = wrap;
        wrap1$i = second;
        wrap1$size_log2 = size_log2;
        wrap1$mode = wrap;
        i0 = wrap0$wrapped;
        i1 = wrap1$wrapped;
    end
    
endmodule // texture_address$across


module texture_address$across$wrap0(i,size_log2,mode,wrapped);
    
    // Module arguments
    input wire  [21:0] i;
    input wire  [3:0] size_log2;
    input wire  [1:0] mode;
    output reg  [12:0] wrapped;
    
    // Local signals
    reg  [21:0] n;
    reg  [21:0] p;
    
    // Update code
    always @(*) begin
        n = ((32'h1) & 22'h3fffff) << ((size_log2) & 22'h3fffff);
        wrapped = ((i & (n - 32'h1)) & 13'h1fff);
        p = i & ((n << 32'h1) - 32'h1);
        if (mode == 32'h1) begin
            wrapped = ((p) & 13'h1fff);
            if (p >= n) begin
                wrapped = (((n << 32'h1) - 32'h1 - p) & 13'h1fff);
            end
        end
        if (mode == 32'h2) begin
            wrapped = ((i) & 13'h1fff);
            if (i[32'h15]) begin
                wrapped = 32'h0;
            end
            else if (i >= n) begin
                wrapped = ((n - 32'h1) & 13'h1fff);
            end
        end
    end
    
endmodule // texture_address$across$wrap0


module texture_address$across$wrap1(i,size_log2,mode,wrapped);
    
    // Module arguments
    input wire  [21:0] i;
    input wire  [3:0] size_log2;
    input wire  [1:0] mode;
    output reg  [12:0] wrapped;
    
    // Local signals
    reg  [21:0] n;
    reg  [21:0] p;
    
    // Update code
    always @(*) begin
        n = ((32'h1) & 22'h3fffff) << ((size_log2) & 22'h3fffff);
        wrapped = ((i & (n - 32'h1)) & 13'h1fff);
        p = i & ((n << 32'h1) - 32'h1);
        if (mode == 32'h1) begin
            wrapped = ((p) & 13'h1fff);
            if (p >= n) begin
                wrapped = (((n << 32'h1) - 32'h1 - p) & 13'h1fff);
            end
        end
        if (mode == 32'h2) begin
            wrapped = ((i) & 13'h1fff);
            if (i[32'h15]) begin
                wrapped = 32'h0;
            end
            else if (i >= n) begin
                wrapped = ((n - 32'h1) & 13'h1fff);
            end
        end
    end
    
endmodule // texture_address$across$wrap1


module texture_address$up(coord,size_log2,linear,wrap,i0,i1,frac);
    
    // Module arguments
    input wire  [28:0] coord;
    input wire  [3:0] size_log2;
    input wire  linear;
    input wire  [1:0] wrap;
    output reg  [12:0] i0;
    output reg  [12:0] i1;
    output reg  [7:0] frac;
    
    // Stub signals
    reg  [21:0] wrap0$i;
    reg  [3:0] wrap0$size_log2;
    reg  [1:0] wrap0$mode;
    wire  [12:0] wrap0$wrapped;
    reg  [21:0] wrap1$i;
    reg  [3:0] wrap1$size_log2;
    reg  [1:0] wrap1$mode;
    wire  [12:0] wrap1$wrapped;
    
    // Local signals
    reg  [29:0] wide;
    reg  [29:0] u;
    reg  [21:0] first;
    reg  [21:0] second;
    
    // Sub module instances
    texture_address$up$wrap0 wrap0(
        .i(wrap0$i),
        .size_log2(wrap0$size_log2),
        .mode(wrap0$mode),
        .wrapped(wrap0$wrapped)
    );
    texture_address$up$wrap1 wrap1(
        .i(wrap1$i),
        .size_log2(wrap1$size_log2),
        .mode(wrap1$mode),
        .wrapped(wrap1$wrapped)
    );
    
    // Update code
    always @(*) begin
        wide = ((coord) & 30'h3fffffff);
        if (coord[32'h1c]) begin
            wide = ((coord) & 30'h3fffffff) | ((32'h20000000) & 30'h3fffffff);
        end
        u = wide >> (((32'hc) & 30'h3fffffff) - ((size_log2) & 30'h3fffffff));
        if (coord[32'h1c]) begin
            u = (wide >> (((32'hc) & 30'h3fffffff) - ((size_log2) & 30'h3fffffff))) | ~(((32'h3fffffff) & 30'h3fffffff) >> (((32'hc) & 30'h3fffffff) - ((size_log2) & 30'h3fffffff)));
        end
        if (linear) begin
            u = u - ((32'h80) & 30'h3fffffff);
        end
        first = u[(32'h8)+:(22)];
        second = first;
        frac = 32'h0;
        if (linear) begin
            second = first + 32'h1;
            frac = u[(32'h0)+:(8)];
        end
        wrap0$i = first;
        wrap0$size_log2 = size_log2;
        wrap0$mode = wrap;
        wrap1$i = second;
        wrap1$size_log2 = size_log2;
        wrap1$mode = wrap;
        i0 = wrap0$wrapped;
        i1 = wrap1$wrapped;
    end
    
endmodule // texture_address$up


module texture_address$up$wrap0(i,size_log2,mode,wrapped);
    
    // Module arguments
    input wire  [21:0] i;
    input wire  [3:0] size_log2;
    input wire  [1:0] mode;
    output reg  [12:0] wrapped;
    
    // Local signals
    reg  [21:0] n;
    reg  [21:0] p;
    
    // Update code
    always @(*) begin
        n = ((32'h1) & 22'h3fffff) << ((size_log2) & 22'h3fffff);
        wrapped = ((i & (n - 32'h1)) & 13'h1fff);
        p = i & ((n << 32'h1) - 32'h1);
        if (mode == 32'h1) begin
            wrapped = ((p) & 13'h1fff);
            if (p >= n) begin
                wrapped = (((n << 32'h1) - 32'h1 - p) & 13'h1fff);
            end
        end
        if (mode == 32'h2) begin
            wrapped = ((i) & 13'h1fff);
            if (i[32'h15]) begin
                wrapped = 32'h0;
            end
            else if (i >= n) begin
                wrapped = ((n - 32'h1) & 13'h1fff);
            end
        end
    end
    
endmodule // texture_address$up$wrap0


module texture_address$up$wrap1(i,size_log2,mode,wrapped);
    
    // Module arguments
    input wire  [21:0] i;
    input wire  [3:0] size_log2;
    input wire  [1:0] mode;
    output reg  [12:0] wrapped;
    
    // Local signals
    reg  [21:0] n;
    reg  [21:0] p;
    
    // Update code
    always @(*) begin
        n = ((32'h1) & 22'h3fffff) << ((size_log2) & 22'h3fffff);
        wrapped = ((i & (n - 32'h1)) & 13'h1fff);
        p = i & ((n << 32'h1) - 32'h1);
        if (mode == 32'h1) begin
            wrapped = ((p) & 13'h1fff);
            if (p >= n) begin
                wrapped = (((n << 32'h1) - 32'h1 - p) & 13'h1fff);
            end
        end
        if (mode == 32'h2) begin
            wrapped = ((i) & 13'h1fff);
            if (i[32'h15]) begin
                wrapped = 32'h0;
            end
            else if (i >= n) begin
                wrapped = ((n - 32'h1) & 13'h1fff);
            end
        end
    end
    
endmodule // texture_address$up$wrap1


module texture_address$word$0(i,j,first,pw,ph,bank,addr);
    
    // Module arguments
    input wire  [12:0] i;
    input wire  [12:0] j;
    input wire  [25:0] first;
    input wire  [3:0] pw;
    input wire  [3:0] ph;
    output reg  [1:0] bank;
    output reg  [25:0] addr;
    
    // Update code
    always @(*) begin
        bank = (((j[(32'h0)+:(1)]) & 2'h3) << 32'h1) | ((i[(32'h0)+:(1)]) & 2'h3);
        addr = first + (((bank) & 26'h3ffffff) << (((pw) & 26'h3ffffff) + ((ph) & 26'h3ffffff))) + (((j >> 32'h1) & 26'h3ffffff) << ((pw) & 26'h3ffffff)) + ((i >> 32'h1) & 26'h3ffffff);
    end
    
endmodule // texture_address$word$0


module texture_address$word$1(i,j,first,pw,ph,bank,addr);
    
    // Module arguments
    input wire  [12:0] i;
    input wire  [12:0] j;
    input wire  [25:0] first;
    input wire  [3:0] pw;
    input wire  [3:0] ph;
    output reg  [1:0] bank;
    output reg  [25:0] addr;
    
    // Update code
    always @(*) begin
        bank = (((j[(32'h0)+:(1)]) & 2'h3) << 32'h1) | ((i[(32'h0)+:(1)]) & 2'h3);
        addr = first + (((bank) & 26'h3ffffff) << (((pw) & 26'h3ffffff) + ((ph) & 26'h3ffffff))) + (((j >> 32'h1) & 26'h3ffffff) << ((pw) & 26'h3ffffff)) + ((i >> 32'h1) & 26'h3ffffff);
    end
    
endmodule // texture_address$word$1


module texture_address$word$2(i,j,first,pw,ph,bank,addr);
    
    // Module arguments
    input wire  [12:0] i;
    input wire  [12:0] j;
    input wire  [25:0] first;
    input wire  [3:0] pw;
    input wire  [3:0] ph;
    output reg  [1:0] bank;
    output reg  [25:0] addr;
    
    // Update code
    always @(*) begin
        bank = (((j[(32'h0)+:(1)]) & 2'h3) << 32'h1) | ((i[(32'h0)+:(1)]) & 2'h3);
        addr = first + (((bank) & 26'h3ffffff) << (((pw) & 26'h3ffffff) + ((ph) & 26'h3ffffff))) + (((j >> 32'h1) & 26'h3ffffff) << ((pw) & 26'h3ffffff)) + ((i >> 32'h1) & 26'h3ffffff);
    end
    
endmodule // texture_address$word$2


module texture_address$word$3(i,j,first,pw,ph,bank,addr);
    
    // Module arguments
    input wire  [12:0] i;
    input wire  [12:0] j;
    input wire  [25:0] first;
    input wire  [3:0] pw;
    input wire  [3:0] ph;
    output reg  [1:0] bank;
    output reg  [25:0] addr;
    
    // Update code
    always @(*) begin
        bank = (((j[(32'h0)+:(1)]) & 2'h3) << 32'h1) | ((i[(32'h0)+:(1)]) & 2'h3);
        addr = first + (((bank) & 26'h3ffffff) << (((pw) & 26'h3ffffff) + ((ph) & 26'h3ffffff))) + (((j >> 32'h1) & 26'h3ffffff) << ((pw) & 26'h3ffffff)) + ((i >> 32'h1) & 26'h3ffffff);
    end
    
endmodule // texture_address$word$3
